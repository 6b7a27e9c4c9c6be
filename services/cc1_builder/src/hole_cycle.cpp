#include "hole_cycle.hpp"

#include <algorithm>
#include <cmath>

#include "toolpath_curve.hpp"

namespace ncbridge::cc1_builder {

namespace {

using setup::ToolType;

template <class Op>
Op drilling_type(const HoleCycle& c, const std::string& id, double top) {
  Op op;
  op.its_id = id;
  op.retract_plane = std::abs(c.r - top);
  op.its_tool = c.tool;
  op.its_technology = c.technology;
  op.its_machine_functions = c.machine_functions;
  op.cutting_depth = std::abs(top - c.bottom);
  if (c.p > 0) op.dwell_time_bottom = c.p;
  return op;
}

std::string_view operation_word(std::uint16_t g, ToolType tool) {
  switch (g) {
    case 730: case 830: return "PECK DRILL";
    case 840: case 841: case 740: return "TAP";
    case 860: case 870: case 880: return "BORE";
    case 850: case 890: return tool == ToolType::Reamer ? "REAM" : "BORE";
    default: break;
  }
  switch (tool) {
    case ToolType::CenterDrill: case ToolType::SpotDrill: return "CENTER DRILL";
    case ToolType::Reamer: return "REAM";
    case ToolType::BoringBar: return "BORE";
    default: return "DRILL";
  }
}

}  // namespace

void HoleCycle::observe(bool feed, double normal_from, double normal_to) {
  const double into = (r >= bottom) ? normal_from - normal_to : normal_to - normal_from;  // > 0 going in
  if (feed && into > 0 && !first_peck_bottom) {
    first_peck_bottom = normal_to;
    after_first_peck = true;
  } else if (after_first_peck && into < 0 && !first_peck_retract) {
    first_peck_retract = normal_to;
  }
}

HoleResult make_hole(const HoleCycle& c, const setup::Tool& tool, const std::optional<setup::Stock>& stock,
                     double diameter_tolerance, int number) {
  const double direction = c.r >= c.bottom ? 1.0 : -1.0;  // the hole axis points out of the material
  double top = c.r;
  bool through = false;
  if (stock && c.normal_axis == 2 && direction > 0) {
    top = std::clamp(stock->max[2], c.bottom, c.r);
    through = c.bottom <= stock->min[2];
  }
  const double depth = std::abs(top - c.bottom);
  const std::string number_text = std::to_string(number);

  HoleResult result;
  stepnc::RoundHole& hole = result.feature;
  hole.its_id = "HOLE" + number_text + " D" + [&] {
    std::string d = std::to_string(tool.diameter);
    d.erase(d.find_last_not_of('0') + 1);
    if (!d.empty() && d.back() == '.') d.pop_back();
    return d;
  }();
  set(hole.feature_placement.location, c.first_axis, c.first);
  set(hole.feature_placement.location, c.second_axis, c.second);
  set(hole.feature_placement.location, c.normal_axis, top);
  hole.feature_placement.axis = unit_axis(c.normal_axis, direction);
  hole.feature_placement.ref_direction = unit_axis(c.first_axis);
  hole.depth.position.location = stepnc::CartesianPoint{0, 0, -depth};
  hole.diameter = {tool.diameter, diameter_tolerance, diameter_tolerance, 3};
  if (through) {
    hole.bottom_condition = stepnc::ThroughBottomCondition{};
  } else if (tool.type == ToolType::Drill || tool.type == ToolType::CenterDrill || tool.type == ToolType::SpotDrill) {
    hole.bottom_condition = stepnc::ConicalHoleBottom{tool.point_angle > 0 ? tool.point_angle : 118.0};
  } else {
    hole.bottom_condition = stepnc::FlatHoleBottom{};
  }

  const std::string id = std::string(operation_word(c.g_code_x10, tool.type)) + " " + hole.its_id;
  switch (c.g_code_x10) {
    case 730: case 830: {
      if (c.q > 0) {
        auto op = drilling_type<stepnc::MultistepDrilling>(c, id, top);
        op.first_depth = c.q;
        op.depth_of_step = c.q;
        op.retract_distance = (c.first_peck_bottom && c.first_peck_retract)
                                  ? std::abs(*c.first_peck_retract - *c.first_peck_bottom) : 0.0;
        result.operation = op;
      } else {
        result.operation = drilling_type<stepnc::Drilling>(c, id, top);
      }
      break;
    }
    case 740: case 840: case 841: {
      auto op = drilling_type<stepnc::Tapping>(c, id, top);
      op.compensation_chuck = false;
      result.operation = op;
      break;
    }
    case 850: case 890: {
      if (tool.type == ToolType::Reamer) {
        auto op = drilling_type<stepnc::Reaming>(c, id, top);
        op.feed_on_retract = 1.0;
        result.operation = op;
      } else {
        auto op = drilling_type<stepnc::Boring>(c, id, top);
        op.feed_on_retract = 1.0;
        result.operation = op;
      }
      break;
    }
    case 860: case 880: {
      auto op = drilling_type<stepnc::Boring>(c, id, top);
      op.spindle_stop_at_bottom = true;
      result.operation = op;
      break;
    }
    case 870: result.operation = drilling_type<stepnc::BackBoring>(c, id, top); break;
    default:  // G81, G82 and anything else that drills straight down and back
      switch (tool.type) {
        case ToolType::CenterDrill: case ToolType::SpotDrill:
          result.operation = drilling_type<stepnc::CenterDrilling>(c, id, top);
          break;
        case ToolType::Reamer: result.operation = drilling_type<stepnc::Reaming>(c, id, top); break;
        case ToolType::BoringBar: result.operation = drilling_type<stepnc::Boring>(c, id, top); break;
        case ToolType::Tap: result.operation = drilling_type<stepnc::Tapping>(c, id, top); break;
        default: result.operation = drilling_type<stepnc::Drilling>(c, id, top); break;
      }
  }
  return result;
}

}  // namespace ncbridge::cc1_builder
