#include "ncbridge/material_check/cutter_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ncbridge::material_check {

double CutterShape::height_at(double r) const {
  r = std::clamp(r, 0.0, radius);
  switch (kind) {
    case Kind::Flat: return 0;
    case Kind::Ball: return radius - std::sqrt(std::max(0.0, radius * radius - r * r));
    case Kind::BullNose: {
      const double flat = radius - corner_radius;
      if (r <= flat) return 0;
      const double d = r - flat;
      return corner_radius - std::sqrt(std::max(0.0, corner_radius * corner_radius - d * d));
    }
    case Kind::Cone: return r / std::tan(tip_angle / 2 * std::numbers::pi / 180);
  }
  return 0;
}

CutterShape cutter_of(const stepnc::MillingCuttingTool& tool) {
  using B = stepnc::ToolBody;
  const auto& d = tool.dimension;
  if (!(d.diameter > 0)) throw std::invalid_argument("tool '" + tool.its_id + "' has no positive diameter");
  CutterShape s;
  s.radius = d.diameter / 2;
  switch (tool.body) {
    case B::TwistDrill:
    case B::Centerdrill:
    case B::Countersink:
      s.kind = CutterShape::Kind::Cone;
      // tool_tip_half_angle is half the point angle; centre drills and countersinks are 90.
      s.tip_angle = d.tool_tip_half_angle ? 2 * *d.tool_tip_half_angle : tool.body == B::TwistDrill ? 118 : 90;
      if (!(s.tip_angle > 0 && s.tip_angle < 180)) s.tip_angle = 118;
      break;
    case B::BallEndmill:
      s.kind = CutterShape::Kind::Ball;
      s.corner_radius = s.radius;
      break;
    default: {
      const double rc = d.edge_radius.value_or(0);
      if (rc >= s.radius - 1e-9) {
        s.kind = CutterShape::Kind::Ball;
        s.corner_radius = s.radius;
      } else if (rc > 1e-9) {
        s.kind = CutterShape::Kind::BullNose;
        s.corner_radius = rc;
      }
      break;
    }
  }
  return s;
}

}  // namespace ncbridge::material_check
