#pragma once
// HEIDENHAIN SL (subcontour list) cycles spelled out as moves: cycle 14 names the contours
// (labels), cycle 20 the machining data, 22 roughs out, 23 finishes the floor, 24 the sides.
// The contours are superimposed as on the TNC: a contour the tool runs inside (RL
// counter-clockwise, RR clockwise) is a pocket, one it runs outside an island; the area to
// machine is the pockets' union less the islands'. The motion, as the TNC manual describes it:
//  - 22 ROUGH-OUT: from the clearance height over the first cutting point, layer by layer of the
//    plunging depth Q10 down to the milling depth Q1 less the floor allowance Q4, the area less
//    the tool radius and the side allowance Q3 is cleared parallel to the contour from the
//    inside outward, the rings Q2 x tool radius apart, at the milling feed Q12 in the direction Q9
//    (+1 climb: counter-clockwise about the pocket walls, clockwise about islands); finally back
//    to the clearance height Q7.
//  - 23 FLOOR FINISHING: the same clearing once at the milling depth.
//  - 24 SIDE FINISHING: the walls of pockets and islands at their final size less the allowance
//    Q14, in layers of Q10.
// ncbridge's choices where the manual leaves the path to the control: each ring is entered from
// the set-up clearance above it with a vertical plunge at Q11 (not reciprocating, Q19); the
// arcs of the contours are chords within 0.005 mm, the rings' rounded corners within 0.01 mm; a coarse roughing tool Q18 is not used to
// leave out what it cleared (the whole area is cleared again, said in a COMMENT).
#include <cstdint>
#include <vector>

#include "lowering/dialect_machine.hpp"

namespace ncbridge::interpreter::heidenhain {

struct SlPoint {
  double x = 0, y = 0;
};

struct SlContour {
  std::vector<SlPoint> points;  // closed: the last point joins the first
  bool pocket = true;
};

// Cycle 20 CONTOUR DATA.
struct SlData {
  double depth = 0;            // Q1 (negative: below the surface)
  double overlap = 1;          // Q2
  double side_allowance = 0;   // Q3
  double floor_allowance = 0;  // Q4
  double surface = 0;          // Q5
  double setup = 0;            // Q6
  double clearance = 0;        // Q7 (absolute)
  double direction = 1;        // Q9: +1 climb (counter-clockwise), -1 up-cut
};

enum class SlOperation { RoughOut, FloorFinishing, SideFinishing };

struct SlCall {
  SlOperation operation = SlOperation::RoughOut;
  double plunge_depth = 0;     // Q10
  double plunge_feed = 0;      // Q11 (machine units per minute)
  double milling_feed = 0;     // Q12
  double finish_allowance = 0; // Q14 (side finishing)
  double tool_radius = 0;      // program units
};

void sl_machine(lowering::DialectMachine& m, const std::vector<SlContour>& contours, const SlData& data,
                const SlCall& call, std::uint32_t column);

}  // namespace ncbridge::interpreter::heidenhain
