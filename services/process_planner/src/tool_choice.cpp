#include "tool_choice.hpp"

#include <cmath>

namespace ncbridge::process_planner {

namespace {

constexpr double kSame = 0.01;

bool reaches(const setup::Tool& t, double reach) { return t.flute_length <= 0 || t.flute_length >= reach - 1e-9; }

bool is_end_mill(const setup::Tool& t) { return t.type == setup::ToolType::FlatEndMill; }

}  // namespace

const setup::Tool* face_tool(const setup::ToolList& tools) {
  const setup::Tool* best = nullptr;
  for (const auto& t : tools.tools()) {
    if (t.type == setup::ToolType::FaceMill && t.diameter > 0 && (!best || t.diameter > best->diameter)) best = &t;
  }
  if (best) return best;
  for (const auto& t : tools.tools()) {
    if (is_end_mill(t) && t.diameter > 0 && (!best || t.diameter > best->diameter)) best = &t;
  }
  return best;
}

const setup::Tool* end_mill(const setup::ToolList& tools, double max_diameter, double reach, double min_diameter) {
  const setup::Tool* best = nullptr;
  for (const auto& t : tools.tools()) {
    if (!is_end_mill(t) || !(t.diameter > 0) || t.diameter > max_diameter + 1e-9 || t.diameter < min_diameter - 1e-9) continue;
    if (!reaches(t, reach)) continue;
    if (!best || t.diameter > best->diameter) best = &t;
  }
  return best;
}

const setup::Tool* smallest_end_mill(const setup::ToolList& tools, double reach) {
  const setup::Tool* best = nullptr;
  for (const auto& t : tools.tools()) {
    if (!is_end_mill(t) || !(t.diameter > 0) || !reaches(t, reach)) continue;
    if (!best || t.diameter < best->diameter) best = &t;
  }
  return best;
}

const setup::Tool* end_mill_of(const setup::ToolList& tools, double diameter, double reach) {
  for (const auto& t : tools.tools()) {
    if (is_end_mill(t) && std::abs(t.diameter - diameter) <= kSame && reaches(t, reach)) return &t;
  }
  return nullptr;
}

const setup::Tool* drill_of(const setup::ToolList& tools, double diameter) {
  for (const auto& t : tools.tools()) {
    if (t.type == setup::ToolType::Drill && std::abs(t.diameter - diameter) <= kSame) return &t;
  }
  return nullptr;
}

const setup::Tool* reamer_of(const setup::ToolList& tools, double diameter) {
  for (const auto& t : tools.tools()) {
    if (t.type == setup::ToolType::Reamer && std::abs(t.diameter - diameter) <= kSame) return &t;
  }
  return nullptr;
}

const setup::Tool* pre_drill(const setup::ToolList& tools, double diameter) {
  const setup::Tool* best = nullptr;
  for (const auto& t : tools.tools()) {
    if (t.type != setup::ToolType::Drill) continue;
    const double under = diameter - t.diameter;
    if (under < 0.1 - 1e-9 || under > 0.6 + 1e-9) continue;
    if (!best || t.diameter > best->diameter) best = &t;
  }
  return best;
}

const setup::Tool* centering_tool(const setup::ToolList& tools) {
  const setup::Tool* best = nullptr;
  for (setup::ToolType type : {setup::ToolType::SpotDrill, setup::ToolType::CenterDrill}) {
    for (const auto& t : tools.tools()) {
      if (t.type == type && t.diameter > 0 && (!best || t.diameter < best->diameter)) best = &t;
    }
    if (best) return best;
  }
  return nullptr;
}

const setup::Tool* countersink_tool(const setup::ToolList& tools, double angle, double diameter) {
  for (setup::ToolType type : {setup::ToolType::ChamferMill, setup::ToolType::SpotDrill}) {
    for (const auto& t : tools.tools()) {
      if (t.type == type && std::abs(t.point_angle - angle) <= 0.5 && t.diameter >= diameter - 1e-9) return &t;
    }
  }
  return nullptr;
}

double largest(const setup::ToolList& tools, setup::ToolType type) {
  double d = 0;
  for (const auto& t : tools.tools()) {
    if (t.type == type) d = std::max(d, t.diameter);
  }
  return d;
}

}  // namespace ncbridge::process_planner
