#include "swept_area.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>


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

double squared_distance_to_segment(Point2 p, Point2 a, Point2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const double ex = p.x - (a.x + t * dx), ey = p.y - (a.y + t * dy);
  return ex * ex + ey * ey;
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
      const double d = squared_distance_to_segment(pts[k], pts[i], pts[j]);
      if (d > worst) worst = d, at = k;
    }
    if (worst > tol * tol) {
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
    const double dx = pts.empty() ? 1 : p.x - pts.back().x, dy = pts.empty() ? 1 : p.y - pts.back().y;
    if (dx * dx + dy * dy > 1e-18) pts.push_back(p);
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

namespace {

// The tool's polygonal disk: n vertices at fixed angles (a multiple of 4), symmetric about the
// centre, so that every position of the tool has the very same vertices relative to it.
std::vector<Point2> polygonal_disk(double radius, double tolerance) {
  const int n = circle_vertex_count(radius, tolerance);
  const double step = 2 * std::numbers::pi / n;
  std::vector<Point2> disk(static_cast<std::size_t>(n));
  for (int i = 0; i < n / 2; ++i) {
    disk[static_cast<std::size_t>(i)] = {radius * std::cos(i * step), radius * std::sin(i * step)};
    disk[static_cast<std::size_t>(i + n / 2)] = {-disk[static_cast<std::size_t>(i)].x, -disk[static_cast<std::size_t>(i)].y};
  }
  return disk;
}

// The disk vertex farthest in direction (nx, ny).
std::size_t extreme_vertex(const std::vector<Point2>& disk, double nx, double ny) {
  const auto n = static_cast<long>(disk.size());
  const double step = 2 * std::numbers::pi / static_cast<double>(n);
  const double angle = std::atan2(ny, nx);
  if (!std::isfinite(angle)) return 0;
  const long guess = std::lround(angle / step);
  long best = 0;
  double best_dot = -1e300;
  for (long k = guess - 1; k <= guess + 1; ++k) {
    const long i = ((k % n) + n) % n;
    const double dot = disk[static_cast<std::size_t>(i)].x * nx + disk[static_cast<std::size_t>(i)].y * ny;
    if (dot > best_dot) best_dot = dot, best = i;
  }
  return static_cast<std::size_t>(best);
}

// The outline of the sweep of the disk along a polyline, as one closed curve (Minkowski sum by
// convolution): along the path on the right at the disk's extreme vertex, round the end on the
// disk, back along the left, round the start. Where the path turns away from a side, the disk's
// arc between the two segments' extreme vertices joins them; where it turns towards it, the
// chord of the disk between them. The curve crosses itself wherever the sweep
// overlaps itself, but it winds around every point of the union of the segments' stadiums at
// least once and around no other point (docs/recognition.md, "Geometry"), so the union is the
// points of non-zero winding, with none of the crossings inside it made by stadiums.
Ring sweep_outline(const std::vector<Point2>& path, const std::vector<Point2>& disk) {
  // A segment of no length has no direction: its repeated point is dropped.
  std::vector<Point2> pts;
  pts.reserve(path.size());
  for (const Point2& p : path) {
    if (pts.empty() || std::hypot(p.x - pts.back().x, p.y - pts.back().y) > 0) pts.push_back(p);
  }
  const std::size_t n = disk.size(), half = n / 2;
  Ring out;
  auto at = [&](Point2 p, std::size_t k) { out.push_back({p.x + disk[k].x, p.y + disk[k].y}); };
  if (pts.size() == 1) {
    for (std::size_t k = 0; k < n; ++k) at(pts[0], k);
    return out;
  }
  const std::size_t m = pts.size() - 1;  // segments
  std::vector<Point2> u(m);
  std::vector<std::size_t> right(m);
  for (std::size_t i = 0; i < m; ++i) {
    const double dx = pts[i + 1].x - pts[i].x, dy = pts[i + 1].y - pts[i].y, l = std::hypot(dx, dy);
    u[i] = {dx / l, dy / l};
    right[i] = extreme_vertex(disk, u[i].y, -u[i].x);
  }
  auto left = [&](std::size_t i) { return (right[i] + half) % n; };
  auto arc = [&](Point2 p, std::size_t from, std::size_t to) {  // counter-clockwise, `from` excluded
    for (std::size_t k = (from + 1) % n;; k = (k + 1) % n) {
      at(p, k);
      if (k == to) break;
    }
  };
  // A turn at a vertex, seen from one side: `away` when the path turns away from that side
  // (counter-clockwise for the right side; a reversal counts as turning away from both).
  auto join = [&](Point2 p, std::size_t from, std::size_t to, bool away) {
    if (from == to) return;
    if (away) {
      arc(p, from, to);
    } else {
      at(p, to);
    }
  };
  auto turn = [&](std::size_t i) {  // between segments i - 1 and i: +1 left, -1 right, 0 reversal or straight
    const double cross = u[i - 1].x * u[i].y - u[i - 1].y * u[i].x;
    return cross > 0 ? 1 : cross < 0 ? -1 : 0;
  };
  at(pts[0], right[0]);
  for (std::size_t i = 0; i < m; ++i) {
    if (i > 0) join(pts[i], right[i - 1], right[i], turn(i) >= 0);
    at(pts[i + 1], right[i]);
  }
  arc(pts[m], right[m - 1], left(m - 1));
  for (std::size_t i = m; i-- > 0;) {
    at(pts[i], left(i));
    if (i > 0) join(pts[i], left(i), left(i - 1), turn(i) <= 0);
  }
  arc(pts[0], left(0), right[0]);
  out.pop_back();  // the start again
  return out;
}

// Long paths are cut into pieces of this many segments (sharing their end points), and the
// pieces' outlines, in path order, are united in a balanced tree: neighbours first, so that a
// union meets few crossings and the partial unions higher up carry only their outlines.
constexpr std::size_t kSegmentsPerPiece = 128;

Region union_tree(const std::vector<Ring>& outlines, std::size_t begin, std::size_t end) {
  if (end - begin == 1) return Region::from_winding({outlines[begin]});
  const std::size_t mid = begin + (end - begin) / 2;
  return union_tree(outlines, begin, mid).united(union_tree(outlines, mid, end));
}

}  // namespace

Region swept_area(const std::vector<std::vector<Point2>>& polylines, double radius, double tolerance) {
  const auto disk = polygonal_disk(radius, tolerance);
  std::vector<Ring> outlines;
  for (const auto& line : polylines) {
    const auto pts = simplify_polyline(line, tolerance);
    if (pts.empty()) continue;
    for (std::size_t first = 0;;) {
      const std::size_t last = std::min(pts.size() - 1, first + kSegmentsPerPiece);
      outlines.push_back(sweep_outline({pts.begin() + static_cast<std::ptrdiff_t>(first),
                                        pts.begin() + static_cast<std::ptrdiff_t>(last) + 1},
                                       disk));
      if (last + 1 >= pts.size()) break;
      first = last;
    }
  }
  if (outlines.empty()) return Region();
  return union_tree(outlines, 0, outlines.size());
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
