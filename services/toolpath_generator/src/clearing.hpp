#pragma once
// Where a milling operation's cutter goes: the clearing area of a feature for one cutter, and
// the cuts each strategy makes at one level (closed loops or open paths, in cutting order).
#include <optional>
#include <vector>

#include "part_model.hpp"
#include "planar_paths.hpp"

namespace ncbridge::toolpath_generator {

struct ClearingArea {
  PolygonSet area;     // what the feature removes
  PolygonSet centres;  // where the cutter's axis may go without cutting the finished part
  PolygonSet tight;    // centres whose cutter stays within the area but for the run-out
  PolygonSet loose;    // centres whose cutter still reaches into the area by the run-out
  PolygonSet passes;   // centres along which a pass may run: out of the area by the run-out
  double radius = 0;   // the cutter's
  double offset = 0;   // how far the axis keeps from the part: radius + side allowance
  double run_out = 0;  // how far past an open side the cutter runs
  bool open = false;   // the area opens to the outside of the stock
};

// The clearing area of `f` for a cutter of `radius` leaving `allowance` on the walls, cutting
// down to `floor_z`; empty centres when the cutter does not fit.
ClearingArea clearing_area(const PartModel& part, const ShapedFeature& f, double floor_z, double radius, double allowance,
                           double run_out);

inline double run_out_of(const ClearingArea& c) { return c.run_out; }

// What is left to cut at a level: the area the cutter can reach less what is already cleared.
PolygonSet to_cut(const ClearingArea& c, const PolygonSet& cleared);

// How the loops of an area turn: one direction for all (a strategy's rotation_direction), or
// climb / conventional milling, which depends on the side the material is on (a pocket's
// wall is outside its loop, a profile's part inside) and on the spindle's sense.
struct LoopSense {
  std::optional<bool> counter_clockwise;
  bool climb = true;
  bool spindle_clockwise = true;
};

struct Cut {
  PlanarCurve path;          // a closed loop, or an open path
  bool lift_before = false;  // reach it from above (unidirectional passes), never by a feed link
};

// Offsets of the area's centres, from its boundary inwards by `stepover`, as many as cover what
// is left to cut; `outward` takes them from the inside out.
std::vector<Cut> contour_parallel_cuts(const ClearingArea& c, const PolygonSet& left, double stepover, bool outward,
                                       const LoopSense& sense);
// Parallel passes along `angle` (radians from +X), `stepover` apart, the next to the left of the
// first when `left` (else to its right), alternating in direction when `bidirectional`; then
// contour loops for what they leave.
std::vector<Cut> parallel_cuts(const ClearingArea& c, const PolygonSet& left, double angle, double stepover, bool to_the_left,
                               bool bidirectional, const LoopSense& sense);
// One open path from the inside out, `stepover` between its turns, ending along the walls.
std::vector<Cut> spiral_cuts(const ClearingArea& c, const PolygonSet& left, double stepover, const LoopSense& sense);

// Whether the loop turns the way `sense` asks for a loop of this kind (`hole_ring`: the
// material is inside it).
bool counter_clockwise_for(const LoopSense& sense, bool hole_ring);

}  // namespace ncbridge::toolpath_generator
