// BIDIRECTIONAL and UNIDIRECTIONAL: straight passes across the clearing area's centres along
// the feed direction, a stepover apart towards the stepover side; then contour loops for what
// they leave along the walls (the finishing contour).
#include <algorithm>
#include <cmath>

#include "clearing.hpp"

namespace ncbridge::toolpath_generator {

std::vector<Cut> parallel_cuts(const ClearingArea& c, const PolygonSet& left_in, double angle, double stepover, bool to_the_left,
                               bool bidirectional, const LoopSense& sense) {
  const PolygonSet& base = c.tight.empty() ? c.loose : c.tight;
  std::vector<Cut> out;
  if (base.empty()) return out;
  const Point2 u{std::cos(angle), std::sin(angle)}, v{-u.y, u.x};
  // Across: from a radius less the run-out inside the area's extremes (past an open side the
  // cutter still reaches the corner), but never beyond where its axis may go; along: as far as
  // the passes may run out.
  double vmin = 1e300, vmax = -1e300, umin = 1e300, umax = -1e300;
  double amin = 1e300, amax = -1e300, cmin = 1e300, cmax = -1e300;
  for (const auto& r : c.area.rings()) {
    for (const auto& p : r) amin = std::min(amin, p.x * v.x + p.y * v.y), amax = std::max(amax, p.x * v.x + p.y * v.y);
  }
  for (const auto& r : c.passes.rings()) {
    for (const auto& p : r) {
      const double pu = p.x * u.x + p.y * u.y;
      umin = std::min(umin, pu), umax = std::max(umax, pu);
    }
  }
  const PolygonSet within = c.passes.intersected(c.area);
  for (const auto& r : within.rings()) {
    for (const auto& p : r) cmin = std::min(cmin, p.x * v.x + p.y * v.y), cmax = std::max(cmax, p.x * v.x + p.y * v.y);
  }
  const double reach = c.radius - run_out_of(c);
  vmin = std::max(cmin, amin + reach), vmax = std::min(cmax, amax - reach);
  if (vmin > vmax) vmin = vmax = (std::max(cmin, amin) + std::min(cmax, amax)) / 2;
  (void)base;
  // Passes just inside the extremes (a pass exactly on an edge of the area has no inside).
  const double inset = 1e-4;
  const double first = to_the_left ? vmin + inset : vmax - inset, last = to_the_left ? vmax - inset : vmin + inset;
  const double span = std::abs(last - first), sign = to_the_left ? 1 : -1;
  std::vector<double> positions;
  for (double d = 0; d < span - 1e-6; d += stepover) positions.push_back(first + sign * d);
  positions.push_back(last);
  if (span < 1e-6) positions = {(first + last) / 2};

  PolygonSet left = left_in;
  int emitted = 0;
  for (double t : positions) {
    const Point2 a{t * v.x + (umin - 1) * u.x, t * v.y + (umin - 1) * u.y};
    const Point2 b{t * v.x + (umax + 1) * u.x, t * v.y + (umax + 1) * u.y};
    auto pieces = clip_segment(c.passes, a, b);
    if (pieces.empty()) continue;
    std::vector<PlanarCurve> lines;
    for (const auto& [s, e] : pieces) {
      PlanarCurve line;
      line.segments.emplace_back(LineSegment{s, e});
      lines.push_back(std::move(line));
    }
    const PolygonSet swept = swept_by(lines, c.radius);
    if (swept.intersected(left).area() < 1e-3) continue;
    left = left.minus(swept);
    const bool forward = !bidirectional || emitted % 2 == 0;
    if (!forward) {
      std::reverse(lines.begin(), lines.end());
      for (auto& l : lines) l = l.reversed();
    }
    for (std::size_t k = 0; k < lines.size(); ++k) out.push_back({std::move(lines[k]), !bidirectional && emitted > 0});
    ++emitted;
  }
  if (without_slivers(left, 0.004).area() >= 1e-3) {
    auto loops = contour_parallel_cuts(c, left, stepover, false, sense);
    for (auto& l : loops) out.push_back(std::move(l));
  }
  return out;
}

}  // namespace ncbridge::toolpath_generator
