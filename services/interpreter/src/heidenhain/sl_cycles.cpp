#include "heidenhain/sl_cycles.hpp"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace ncbridge::interpreter::heidenhain {

namespace {

using ClipperLib::Path;
using ClipperLib::Paths;
using lowering::NeutralBlock;

constexpr double kScale = 1e4;  // 0.1 micrometre grid

ClipperLib::IntPoint to_int(const SlPoint& p) {
  return {static_cast<ClipperLib::cInt>(std::llround(p.x * kScale)), static_cast<ClipperLib::cInt>(std::llround(p.y * kScale))};
}

Paths offset(const Paths& in, double delta) {
  ClipperLib::ClipperOffset co;
  co.ArcTolerance = 0.01 * kScale;  // the rounded corners of the rings: chords within 0.01 mm
  co.AddPaths(in, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  Paths out;
  co.Execute(out, delta * kScale);
  ClipperLib::CleanPolygons(out, 0.001 * kScale);
  return out;
}

// The area to machine: the pockets' union less the islands' union.
Paths area_of(const std::vector<SlContour>& contours) {
  Paths pockets, islands;
  for (const SlContour& c : contours) {
    Path p;
    for (const SlPoint& q : c.points) p.push_back(to_int(q));
    if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
    (c.pocket ? pockets : islands).push_back(p);
  }
  ClipperLib::Clipper clip;
  clip.AddPaths(pockets, ClipperLib::ptSubject, true);
  clip.AddPaths(islands, ClipperLib::ptClip, true);
  Paths area;
  clip.Execute(ClipperLib::ctDifference, area, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return area;
}

class Mover {
 public:
  Mover(lowering::DialectMachine& m, std::uint32_t column) : m_(m), column_(column) {}
  void run(NeutralBlock& nb) {
    if (m_.execute(nb)) m_.fail(column_, "An SL cycle ended the program");
    nb.clear();
  }
  void rapid_z(double z) {
    NeutralBlock nb;
    nb.g(0, column_);
    m_.put_axes(nb, std::nullopt, std::nullopt, z, column_);
    run(nb);
  }
  void rapid_xy(double x, double y) {
    NeutralBlock nb;
    nb.g(0, column_);
    m_.put_axes(nb, x, y, std::nullopt, column_);
    run(nb);
  }
  void feed(std::optional<double> x, std::optional<double> y, std::optional<double> z, double f) {
    NeutralBlock nb;
    nb.g(1, column_);
    if (std::fabs(m_.state().feed_rate - f) > 1e-9) nb.add('f', f, column_);
    m_.put_axes(nb, x, y, z, column_);
    run(nb);
  }
  // One closed loop at height z: entered from the set-up clearance above its first point.
  void loop(const Path& p, double z, double above, double plunge_feed, double milling_feed) {
    if (p.size() < 2) return;
    const auto x = [](const ClipperLib::IntPoint& q) { return static_cast<double>(q.X) / kScale; };
    const auto y = [](const ClipperLib::IntPoint& q) { return static_cast<double>(q.Y) / kScale; };
    rapid_z(above);
    rapid_xy(x(p.front()), y(p.front()));
    feed(std::nullopt, std::nullopt, z, plunge_feed);
    for (std::size_t i = 1; i <= p.size(); ++i) {
      const auto& q = p[i % p.size()];
      feed(x(q), y(q), std::nullopt, milling_feed);
    }
  }

 private:
  lowering::DialectMachine& m_;
  std::uint32_t column_;
};

// The loops of an area in the order they are cut: rings from the inside out (the innermost
// first), each ring's loops in the direction of Q9 (Clipper gives outer boundaries
// counter-clockwise, holes clockwise: climb milling with M3). Where rings more than a tool
// radius apart leave a strip between them that no ring reaches (the stepover is larger than the
// radius, Q2 > 1), the strip's outline is cut first: it is never wider than two radii.
std::vector<Path> rings(const Paths& area, double first_inset, double step, bool climb, double reach) {
  std::vector<Paths> layers;
  const Paths region = offset(area, -first_inset);
  Paths ring = region;
  while (!ring.empty()) {
    layers.push_back(ring);
    ring = offset(ring, -step);
  }
  Paths all;
  for (const Paths& l : layers) all.insert(all.end(), l.begin(), l.end());
  Paths rest;
  if (!all.empty()) {
    ClipperLib::ClipperOffset co;
    co.ArcTolerance = 0.01 * kScale;
    co.AddPaths(all, ClipperLib::jtRound, ClipperLib::etClosedLine);
    Paths bands;
    co.Execute(bands, reach * (1 - 1e-4) * kScale);
    ClipperLib::Clipper clip;
    clip.AddPaths(region, ClipperLib::ptSubject, true);
    clip.AddPaths(bands, ClipperLib::ptClip, true);
    clip.Execute(ClipperLib::ctDifference, rest, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  }
  std::vector<Path> loops;
  for (Path p : rest) {
    if (std::fabs(ClipperLib::Area(p)) < 1e-6 * kScale * kScale) continue;
    if (ClipperLib::Orientation(p) != climb) ClipperLib::ReversePath(p);
    loops.push_back(p);
  }
  for (auto it = layers.rbegin(); it != layers.rend(); ++it) {
    for (Path p : *it) {
      if (!climb) ClipperLib::ReversePath(p);
      loops.push_back(p);
    }
  }
  return loops;
}

}  // namespace

void sl_machine(lowering::DialectMachine& m, const std::vector<SlContour>& contours, const SlData& d,
                const SlCall& c, std::uint32_t column) {
  if (contours.empty()) m.fail(column, "SL cycle without contours: define them with CYCL DEF 14");
  if (c.tool_radius <= 0) m.fail(column, "SL cycle: the tool's radius is not known (the tool is not in the tool list)");
  if (c.milling_feed <= 0 || c.plunge_feed <= 0) m.fail(column, "SL cycle without its feeds (Q11, Q12)");
  const Paths area = area_of(contours);
  if (area.empty()) m.fail(column, "SL cycle: the contours leave no area to machine (islands cover the pockets)");
  const bool climb = d.direction >= 0;
  const double step = std::max(1e-3, d.overlap * c.tool_radius);
  const double floor = d.surface - std::fabs(d.depth);
  const double above = d.surface + std::fabs(d.setup);
  Mover move(m, column);
  const double start_z = m.position().z;
  if (std::max(d.clearance, above) > start_z + 1e-9) move.rapid_z(std::max(d.clearance, above));

  std::vector<double> layers;
  const double plunge = std::fabs(c.plunge_depth);
  double bottom = floor;
  double inset = c.tool_radius;
  if (c.operation == SlOperation::RoughOut) {
    bottom = floor + std::fabs(d.floor_allowance);
    inset = c.tool_radius + std::fabs(d.side_allowance);
  } else if (c.operation == SlOperation::SideFinishing) {
    inset = c.tool_radius + std::fabs(c.finish_allowance);
  }
  if (c.operation == SlOperation::FloorFinishing) {
    layers.push_back(floor);
  } else {
    if (plunge <= 0) m.fail(column, "SL cycle without a plunging depth Q10");
    const double total = d.surface - bottom;
    const int n = std::max(1, static_cast<int>(std::ceil(total / plunge - 1e-9)));
    for (int i = 1; i <= n; ++i) layers.push_back(std::max(bottom, d.surface - i * plunge));
  }

  std::vector<Path> loops;
  if (c.operation == SlOperation::SideFinishing) {
    // the walls: the outermost ring only (its outer loops and its holes)
    for (Path p : offset(area, -inset)) {
      if (!climb) ClipperLib::ReversePath(p);
      loops.push_back(p);
    }
  } else {
    // roughing keeps the side allowance; the floor finishing clears to the finished walls less
    // the side allowance (cycle 24 takes it)
    if (c.operation == SlOperation::FloorFinishing) inset = c.tool_radius + std::fabs(d.side_allowance);
    loops = rings(area, inset, step, climb, c.tool_radius);
  }
  if (loops.empty()) m.fail(column, "SL cycle: the tool is too large for the contour");
  for (double z : layers) {
    for (const Path& p : loops) move.loop(p, z, above, c.plunge_feed, c.milling_feed);
  }
  move.rapid_z(std::max(d.clearance, above));
}

}  // namespace ncbridge::interpreter::heidenhain
