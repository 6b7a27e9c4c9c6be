#pragma once
// Shared helpers for cc1_builder tests: the paper's tools and quick access into a project.
#include <string>
#include <variant>
#include <vector>

#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::cc1_builder::testing {

inline setup::ToolList paper_tools() {
  setup::Tool endmill;
  endmill.number = 1;
  endmill.name = "ENDMILL_18MM";
  endmill.type = setup::ToolType::FlatEndMill;
  endmill.diameter = 18;
  endmill.length = 50;
  endmill.flutes = 4;
  setup::Tool drill;
  drill.number = 2;
  drill.name = "DRILL_20MM";
  drill.type = setup::ToolType::Drill;
  drill.diameter = 20;
  drill.length = 70;
  drill.point_angle = 118;
  setup::Tool reamer;
  reamer.number = 3;
  reamer.name = "REAMER_22MM";
  reamer.type = setup::ToolType::Reamer;
  reamer.diameter = 22;
  reamer.length = 50;
  return setup::ToolList({endmill, drill, reamer});
}

inline Options paper_options() {
  Options o;
  o.tools = paper_tools();
  setup::Stock stock;
  stock.min = {0, 0, -50};
  stock.max = {100, 120, 5};
  o.stock = stock;
  return o;
}

// "W" for a machining workingstep, "R" for a rapid movement, in workplan order.
inline std::string workplan_shape(const stepnc::Project& p) {
  std::string s;
  for (const auto& e : p.main_workplan.its_elements) {
    s += std::holds_alternative<stepnc::RapidMovement>(e) ? 'R' : std::holds_alternative<stepnc::WorkpieceProbing>(e) ? 'P' : 'W';
  }
  return s;
}

inline const stepnc::MachiningWorkingstep& workingstep(const stepnc::Project& p, std::size_t nth) {
  std::size_t seen = 0;
  for (const auto& e : p.main_workplan.its_elements) {
    if (const auto* ws = std::get_if<stepnc::MachiningWorkingstep>(&e)) {
      if (seen++ == nth) return *ws;
    }
  }
  throw std::out_of_range("no such workingstep");
}

inline const stepnc::RapidMovement& rapid_movement(const stepnc::Project& p, std::size_t nth) {
  std::size_t seen = 0;
  for (const auto& e : p.main_workplan.its_elements) {
    if (const auto* r = std::get_if<stepnc::RapidMovement>(&e)) {
      if (seen++ == nth) return *r;
    }
  }
  throw std::out_of_range("no such rapid movement");
}

inline const stepnc::Operation& operation_of(const stepnc::Project& p, std::size_t nth_ws) {
  return p.operation(workingstep(p, nth_ws).its_operation);
}

// All cutter-location points of the cutting trajectories of an operation, in order.
inline std::vector<stepnc::CartesianPoint> polyline_points(const stepnc::Operation& op) {
  std::vector<stepnc::CartesianPoint> pts;
  for (const auto& t : stepnc::machining_operation(op).its_toolpath->its_list) {
    for (const auto& seg : t.basiccurve.segments) {
      if (const auto* l = std::get_if<stepnc::Polyline>(&seg)) pts.insert(pts.end(), l->points.begin(), l->points.end());
    }
  }
  return pts;
}

}  // namespace ncbridge::cc1_builder::testing
