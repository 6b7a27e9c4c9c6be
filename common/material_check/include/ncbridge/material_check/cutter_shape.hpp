#pragma once
// The cutting envelope of a tool turning about a vertical axis, as the height of its cutting
// surface above the tool tip at each distance from the axis: flat (end mills, face mills,
// reamers, taps, boring bars), ball, bull nose (a corner radius) and cone (drills, centre and
// spot drills, countersinks: the point angle). Lengths in mm.
#include <optional>
#include <string>

#include "ncbridge/stepnc/resources.hpp"

namespace ncbridge::material_check {

struct CutterShape {
  enum class Kind { Flat, Ball, BullNose, Cone };
  Kind kind = Kind::Flat;
  double radius = 0;         // half the cutting diameter
  double corner_radius = 0;  // BullNose (Ball: = radius)
  double tip_angle = 118;    // Cone: the included point angle, degrees

  // Height of the cutting surface above the tip at `r` from the axis (0 <= r <= radius).
  double height_at(double r) const;
};

// The shape of an ISO 14649 milling cutting tool: its body and MILLING_TOOL_DIMENSION
// (diameter, tool_tip_half_angle, edge_radius). Throws std::invalid_argument for a tool
// without a positive diameter.
CutterShape cutter_of(const stepnc::MillingCuttingTool& tool);

}  // namespace ncbridge::material_check
