// CONTOUR_SPIRAL: one open path winding out from the middle, blending each offset loop into the
// next over a turn, then a last turn along the walls that stops just short of where it began
// (so that the path never closes on itself).
#include <algorithm>
#include <cmath>

#include "clearing.hpp"

namespace ncbridge::toolpath_generator {

std::vector<Cut> spiral_cuts(const ClearingArea& c, const PolygonSet& left, double stepover, const LoopSense& sense) {
  const PolygonSet& base = c.tight.empty() ? c.loose : c.tight;
  std::vector<PlanarCurve> loops;  // outside in
  for (int i = 0; i < 100000; ++i) {
    const PolygonSet region = i == 0 ? base : base.offset(-i * stepover, kArcTolerance);
    if (region.empty()) break;
    if (region.rings().size() != 1) return contour_parallel_cuts(c, left, stepover, true, sense);  // it branches
    PlanarCurve loop = curve_from_ring(region.rings().front());
    if ((loop.signed_area() > 0) != counter_clockwise_for(sense, false)) loop = loop.reversed();
    loops.push_back(std::move(loop));
  }
  if (loops.size() < 2) return contour_parallel_cuts(c, left, stepover, true, sense);
  std::reverse(loops.begin(), loops.end());  // inside out
  PlanarCurve spiral;
  Point2 at = material_check::start_of(loops.front().segments.front());
  for (std::size_t i = 0; i + 1 < loops.size(); ++i) {
    const PlanarCurve inner = loop_from(loops[i], at);
    const PlanarCurve& outer = loops[i + 1];
    const auto samples = inner.points(0.01);
    const double length = inner.length();
    const int n = std::max(64, static_cast<int>(std::ceil(length / 0.5)));
    // Resample the inner loop evenly by length and move each point towards the outer loop by
    // the share of the turn done.
    std::vector<Point2> even;
    double travelled = 0;
    std::size_t k = 0;
    std::vector<double> cumulative{0};
    std::vector<Point2> pts = samples;
    pts.push_back(samples.front());
    for (std::size_t j = 1; j < pts.size(); ++j) cumulative.push_back(cumulative.back() + distance(pts[j - 1], pts[j]));
    for (int j = 0; j <= n; ++j) {
      travelled = cumulative.back() * j / n;
      while (k + 1 < cumulative.size() - 1 && cumulative[k + 1] < travelled) ++k;
      const double seg = cumulative[k + 1] - cumulative[k];
      const double f = seg > 0 ? (travelled - cumulative[k]) / seg : 0;
      const Point2 p{pts[k].x + (pts[k + 1].x - pts[k].x) * f, pts[k].y + (pts[k + 1].y - pts[k].y) * f};
      const Point2 q = closest_place(outer, p).point;
      const double w = static_cast<double>(j) / n;
      even.push_back({p.x + (q.x - p.x) * w, p.y + (q.y - p.y) * w});
    }
    for (std::size_t j = 1; j < even.size(); ++j) {
      if (distance(even[j - 1], even[j]) > 1e-7) spiral.segments.emplace_back(LineSegment{even[j - 1], even[j]});
    }
    at = even.back();
  }
  // The walls: a last turn from where the spiral reached them, stopping 0.05 mm short.
  const PlanarCurve lap = loop_from(loops.back(), at);
  const PlanarCurve walls = leading_part(lap, std::max(0.0, lap.length() - 0.05));
  spiral.segments.insert(spiral.segments.end(), walls.segments.begin(), walls.segments.end());
  return {{std::move(spiral), false}};
}

}  // namespace ncbridge::toolpath_generator
