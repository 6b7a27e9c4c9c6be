#pragma once
// Test support: writes synthetic toolpath workingsteps move by move.
#include <vector>

#include "ncbridge/feature_recognizer/toolpath.hpp"

namespace ncbridge::test_support {

inline setup::Tool make_tool(int number, setup::ToolType type, double diameter, double point_angle = 0) {
  setup::Tool t;
  t.number = number;
  t.type = type;
  t.diameter = diameter;
  t.point_angle = point_angle;
  return t;
}

class ToolpathBuilder {
 public:
  // Starts a new workingstep with `tool`, at the current position.
  ToolpathBuilder& workingstep(const setup::Tool& tool) {
    feature_recognizer::ToolpathWorkingstep ws;
    ws.tool = tool;
    ws.start = at_;
    steps_.push_back(ws);
    return *this;
  }
  ToolpathBuilder& rapid(double x, double y, double z) { return add(feature_recognizer::MoveKind::Rapid, x, y, z); }
  ToolpathBuilder& feed(double x, double y, double z) { return add(feature_recognizer::MoveKind::Linear, x, y, z); }
  ToolpathBuilder& arc(double x, double y, double z, double cx, double cy, bool clockwise, int turns = 1) {
    add(feature_recognizer::MoveKind::Arc, x, y, z);
    auto& m = steps_.back().moves.back();
    m.center_x = cx, m.center_y = cy, m.clockwise = clockwise, m.turns = turns;
    return *this;
  }
  // A drilling pass: rapid above the hole, feed to the bottom, rapid out.
  ToolpathBuilder& drill(double x, double y, double r_plane, double bottom) {
    return rapid(x, y, r_plane).feed(x, y, bottom).rapid(x, y, r_plane);
  }
  const std::vector<feature_recognizer::ToolpathWorkingstep>& steps() const { return steps_; }

 private:
  ToolpathBuilder& add(feature_recognizer::MoveKind kind, double x, double y, double z) {
    feature_recognizer::Move m;
    m.kind = kind;
    m.end = {x, y, z};
    steps_.back().moves.push_back(m);
    at_ = m.end;
    return *this;
  }
  std::vector<feature_recognizer::ToolpathWorkingstep> steps_;
  feature_recognizer::Point3 at_{0, 0, 50};
};

}  // namespace ncbridge::test_support
