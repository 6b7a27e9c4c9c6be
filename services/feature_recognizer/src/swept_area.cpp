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
  const long guess = std::lround(std::atan2(ny, nx) / step);
  long best = 0;
  double best_dot = -1e300;
  for (long k = guess - 1; k <= guess + 1; ++k) {
    const long i = ((k % n) + n) % n;
    const double dot = disk[static_cast<std::size_t>(i)].x * nx + disk[static_cast<std::size_t>(i)].y * ny;
    if (dot > best_dot) best_dot = dot, best = i;
  }
  return static_cast<std::size_t>(best);
}

Ring moved(const std::vector<Point2>& disk, Point2 at) {
  Ring ring;
  ring.reserve(disk.size());
  for (const auto& v : disk) ring.push_back({at.x + v.x, at.y + v.y});
  return ring;
}

// The sweep of the disk along a polyline as convex pieces whose union is the union of the
// stadiums of its segments: the disk at both ends; per segment the parallelogram between the
// disk's extreme vertices across it (a stadium is the two disks and that parallelogram); at each
// inner vertex the sector of the disk there on the outer side of the turn, between the two
// segments' extreme vertices (the rest of that disk lies in the neighbouring pieces).
void sweep_pieces(const std::vector<Point2>& pts, const std::vector<Point2>& disk, double radius, std::vector<Ring>& out) {
  out.push_back(moved(disk, pts.front()));
  if (pts.size() == 1) return;
  const std::size_t n = disk.size();
  auto unit = [&](std::size_t i) {
    const double dx = pts[i + 1].x - pts[i].x, dy = pts[i + 1].y - pts[i].y, l = std::hypot(dx, dy);
    return Point2{dx / l, dy / l};
  };
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Point2 u = unit(i), a = pts[i], b = pts[i + 1];
    const auto right = disk[extreme_vertex(disk, u.y, -u.x)], left = disk[extreme_vertex(disk, -u.y, u.x)];
    out.push_back({{a.x + right.x, a.y + right.y}, {b.x + right.x, b.y + right.y}, {b.x + left.x, b.y + left.y},
                   {a.x + left.x, a.y + left.y}});
    if (i + 2 >= pts.size()) break;
    const Point2 w = unit(i + 1);
    const double cross = u.x * w.y - u.y * w.x, dot = u.x * w.x + u.y * w.y;
    if (cross == 0 && dot > 0) continue;  // straight on
    // A left turn (or a reversal) opens the right side: its extreme vertices turn
    // counter-clockwise; a right turn opens the left side, clockwise.
    const bool left_turn = cross > 0 || (cross == 0 && dot < 0);
    const std::size_t from = left_turn ? extreme_vertex(disk, u.y, -u.x) : extreme_vertex(disk, -u.y, u.x);
    const std::size_t to = left_turn ? extreme_vertex(disk, w.y, -w.x) : extreme_vertex(disk, -w.y, w.x);
    if (from == to) continue;
    const std::size_t steps = left_turn ? (to + n - from) % n : (from + n - to) % n;
    // The sector's apex is not the vertex itself but a point of the disk behind it, inside both
    // segments' parallelograms: the sector then overlaps them instead of meeting them along the
    // lines through the vertex, where rounding to the grid would leave slivers.
    const Point2 mid{disk[from].x + disk[to].x, disk[from].y + disk[to].y};
    const double mid_length = std::hypot(mid.x, mid.y);
    const Point2 m = mid_length > 1e-9 * radius ? Point2{mid.x / mid_length, mid.y / mid_length} : u;
    Ring sector{{b.x - 0.5 * radius * m.x, b.y - 0.5 * radius * m.y}};
    for (std::size_t k = 0; k <= steps; ++k) {
      const auto& v = disk[left_turn ? (from + k) % n : (from + n - k) % n];
      sector.push_back({b.x + v.x, b.y + v.y});
    }
    out.push_back(std::move(sector));
  }
  out.push_back(moved(disk, pts.back()));
}

// Pieces taken in path order are near each other: uniting neighbours first resolves their many
// overlaps once, and the partial unions met higher up have only their outlines left.
constexpr std::size_t kPiecesPerLeaf = 64;

Region union_tree(const std::vector<Ring>& pieces, std::size_t begin, std::size_t end) {
  if (end - begin <= kPiecesPerLeaf) {
    return Region::union_of({pieces.begin() + static_cast<std::ptrdiff_t>(begin), pieces.begin() + static_cast<std::ptrdiff_t>(end)});
  }
  const std::size_t mid = begin + (end - begin) / 2;
  return union_tree(pieces, begin, mid).united(union_tree(pieces, mid, end));
}

}  // namespace

Region swept_area(const std::vector<std::vector<Point2>>& polylines, double radius, double tolerance) {
  const auto disk = polygonal_disk(radius, tolerance);
  std::vector<Ring> pieces;
  for (const auto& line : polylines) {
    const auto pts = simplify_polyline(line, tolerance);
    if (!pts.empty()) sweep_pieces(pts, disk, radius, pieces);
  }
  if (pieces.empty()) return Region();
  return union_tree(pieces, 0, pieces.size());
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
