#include "swept_area.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "exact_union.hpp"

namespace ncbridge::feature_recognizer {

int circle_vertex_count(double radius, double tolerance) {
  if (radius <= tolerance) return 8;
  const double half_angle = std::acos(1.0 - tolerance / radius);
  const int n = static_cast<int>(std::ceil(std::numbers::pi / half_angle));
  return std::clamp((n + 3) / 4 * 4, 8, 720);  // a multiple of 4: walls along x and y lie at the full radius
}

Ring stadium(Point2 a, Point2 b, double radius, double tolerance) {
  // One polygonal disk for every position (vertices at fixed angles, whatever the segment's
  // direction): where paths of two layers pass the same points their swept areas have the same
  // vertices, and a move inside an area already swept adds nothing, not slivers between
  // differently turned polygons. The stadium is the convex hull of the disk at a and at b.
  const int n = circle_vertex_count(radius, tolerance);
  const double step = 2 * std::numbers::pi / n;
  std::vector<Point2> disk;
  disk.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) disk.push_back({radius * std::cos(i * step), radius * std::sin(i * step)});
  Ring ring;
  if (std::hypot(b.x - a.x, b.y - a.y) < 1e-9) {
    for (const auto& v : disk) ring.push_back({a.x + v.x, a.y + v.y});
    return ring;
  }
  std::vector<Point2> pts;
  pts.reserve(2 * disk.size());
  for (const auto& v : disk) pts.push_back({a.x + v.x, a.y + v.y}), pts.push_back({b.x + v.x, b.y + v.y});
  std::sort(pts.begin(), pts.end(), [](const Point2& p, const Point2& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
  // Andrew's monotone chain: lower hull then upper hull, counter-clockwise, collinear points out.
  auto cross = [](const Point2& o, const Point2& p, const Point2& q) {
    return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x);
  };
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = ring.size();
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const auto& p = pass == 0 ? pts[k] : pts[pts.size() - 1 - k];
      while (ring.size() >= base + 2 && cross(ring[ring.size() - 2], ring.back(), p) <= 0) ring.pop_back();
      ring.push_back(p);
    }
    ring.pop_back();  // the last point starts the other chain
  }
  return ring;
}

namespace {

double distance_to_segment(Point2 p, Point2 a, Point2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

void douglas_peucker(const std::vector<Point2>& pts, std::size_t first, std::size_t last, double tol,
                     std::vector<bool>& keep) {
  // Iterative, so long paths cannot overflow the stack.
  std::vector<std::pair<std::size_t, std::size_t>> todo{{first, last}};
  while (!todo.empty()) {
    auto [i, j] = todo.back();
    todo.pop_back();
    if (j <= i + 1) continue;
    double worst = -1;
    std::size_t at = i;
    for (std::size_t k = i + 1; k < j; ++k) {
      const double d = distance_to_segment(pts[k], pts[i], pts[j]);
      if (d > worst) worst = d, at = k;
    }
    if (worst > tol) {
      keep[at] = true;
      todo.push_back({i, at});
      todo.push_back({at, j});
    }
  }
}

}  // namespace

std::vector<Point2> simplify_polyline(const std::vector<Point2>& points, double tolerance) {
  std::vector<Point2> pts;
  for (const auto& p : points) {
    if (pts.empty() || std::hypot(p.x - pts.back().x, p.y - pts.back().y) > 1e-9) pts.push_back(p);
  }
  if (pts.size() <= 2) return pts;
  std::vector<bool> keep(pts.size(), false);
  keep.front() = keep.back() = true;
  douglas_peucker(pts, 0, pts.size() - 1, tolerance, keep);
  std::vector<Point2> out;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (keep[i]) out.push_back(pts[i]);
  }
  return out;
}

Region swept_area(const std::vector<std::vector<Point2>>& polylines, double radius, double tolerance) {
  std::vector<Ring> pieces;
  for (const auto& line : polylines) {
    const auto pts = simplify_polyline(line, tolerance);
    if (pts.size() == 1) pieces.push_back(stadium(pts[0], pts[0], radius, tolerance));
    for (std::size_t i = 1; i < pts.size(); ++i) pieces.push_back(stadium(pts[i - 1], pts[i], radius, tolerance));
  }
  return exact_union(pieces);
}

Region boundary_band(const Region& region, double radius, double tolerance) {
  std::vector<std::vector<Point2>> loops;
  for (const auto& pwh : region.polygons()) {
    auto close = [&](const Ring& ring) {
      std::vector<Point2> loop(ring.begin(), ring.end());
      if (!loop.empty()) loop.push_back(loop.front());
      loops.push_back(std::move(loop));
    };
    close(pwh.outer);
    for (const auto& h : pwh.holes) close(h);
  }
  return swept_area(loops, radius, tolerance);
}

}  // namespace ncbridge::feature_recognizer
