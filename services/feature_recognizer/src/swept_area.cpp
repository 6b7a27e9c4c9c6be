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
  return std::clamp(n + (n % 2), 8, 720);
}

Ring stadium(Point2 a, Point2 b, double radius, double tolerance) {
  const int n = circle_vertex_count(radius, tolerance);
  const double step = 2 * std::numbers::pi / n;
  Ring ring;
  const double dx = b.x - a.x, dy = b.y - a.y;
  if (std::hypot(dx, dy) < 1e-9) {
    for (int i = 0; i < n; ++i) ring.push_back({a.x + radius * std::cos(i * step), a.y + radius * std::sin(i * step)});
    return ring;
  }
  const double dir = std::atan2(dy, dx);
  const int half = n / 2;
  // Around b from dir-90° to dir+90°, then around a from dir+90° to dir+270°: counter-clockwise.
  for (int i = 0; i <= half; ++i) {
    const double t = dir - std::numbers::pi / 2 + i * step;
    ring.push_back({b.x + radius * std::cos(t), b.y + radius * std::sin(t)});
  }
  for (int i = 0; i <= half; ++i) {
    const double t = dir + std::numbers::pi / 2 + i * step;
    ring.push_back({a.x + radius * std::cos(t), a.y + radius * std::sin(t)});
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
