#pragma once
// Hand-made canonical call streams for builder tests: one method per canonical call, each call
// tagged with the next source line so tests can check where workingsteps came from.
#include <vector>

#include "ncbridge/canonical/call.hpp"

namespace ncbridge::cc1_builder::testing {

class CanonicalStream {
 public:
  std::vector<canonical::Call> calls;

  CanonicalStream& add(canonical::Data data) {
    calls.push_back({std::move(data), {0, ++line_, -1}, cycle_});
    return *this;
  }
  CanonicalStream& inches() { return add(canonical::UseLengthUnits{canonical::Units::Inches}); }
  CanonicalStream& tool(int n) {
    add(canonical::SelectTool{n});
    return add(canonical::ChangeTool{n});
  }
  CanonicalStream& spindle_cw(double rpm) {
    add(canonical::SetSpindleSpeed{0, rpm});
    return add(canonical::StartSpindleClockwise{0});
  }
  CanonicalStream& spindle_ccw(double rpm) {
    add(canonical::SetSpindleSpeed{0, rpm});
    return add(canonical::StartSpindleCounterclockwise{0});
  }
  CanonicalStream& feed(double f) { return add(canonical::SetFeedRate{f}); }
  CanonicalStream& rapid(double x, double y, double z) { return add(canonical::StraightTraverse{pose(x, y, z)}); }
  CanonicalStream& line(double x, double y, double z) { return add(canonical::StraightFeed{pose(x, y, z)}); }
  // XY-plane arc to (x, y, z) about (cx, cy); rotation > 0 = G3 (counter-clockwise).
  CanonicalStream& arc(double x, double y, double z, double cx, double cy, int rotation) {
    return add(canonical::ArcFeed{x, y, cx, cy, rotation, z, 0, 0, 0, 0, 0, 0});
  }
  CanonicalStream& flood(bool on) { return on ? add(canonical::FloodOn{}) : add(canonical::FloodOff{}); }
  CanonicalStream& end() { return add(canonical::ProgramEnd{}); }

  // The calls a G81/G82/G83 hole makes (LinuxCNC order), tagged with a new cycle id.
  CanonicalStream& drill_hole(std::uint16_t g_x10, double x, double y, double r, double z, double clearance,
                              double q = 0, double p = 0) {
    canonical::CycleTag tag;
    tag.cycle_id = ++cycle_id_;
    tag.g_code_x10 = g_x10;
    tag.x = x;
    tag.y = y;
    tag.r = r;
    tag.z = z;
    tag.clearance = clearance;
    tag.q = q;
    tag.p = p;
    cycle_ = tag;
    rapid(x, y, clearance);
    rapid(x, y, r);
    if (q > 0) {
      double depth = r;
      while (depth > z) {
        const double next = std::max(z, depth - q);
        line(x, y, next);
        if (g_x10 == 730) rapid(x, y, next + 0.254); else rapid(x, y, r);
        depth = next;
        if (depth > z && g_x10 == 830) rapid(x, y, depth + 0.254);
      }
    } else {
      line(x, y, z);
      if (p > 0) add(canonical::Dwell{p});
    }
    if (g_x10 == 850) line(x, y, r); else rapid(x, y, r);
    cycle_.reset();
    return *this;
  }

  std::uint32_t current_line() const { return line_; }

 private:
  static canonical::Pose pose(double x, double y, double z) {
    canonical::Pose p;
    p.x = x;
    p.y = y;
    p.z = z;
    return p;
  }
  std::uint32_t line_ = 0;
  std::uint32_t cycle_id_ = 0;
  std::optional<canonical::CycleTag> cycle_;
};

}  // namespace ncbridge::cc1_builder::testing
