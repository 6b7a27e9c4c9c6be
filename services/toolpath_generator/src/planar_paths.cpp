#include "planar_paths.hpp"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncbridge::toolpath_generator {

namespace {

constexpr double kPi = std::numbers::pi;
namespace cl = ClipperLib;

// The signed turn (radians) from the direction a->b to b->c.
double turn(Point2 a, Point2 b, Point2 c) {
  const double t1 = std::atan2(b.y - a.y, b.x - a.x), t2 = std::atan2(c.y - b.y, c.x - b.x);
  double d = t2 - t1;
  while (d > kPi) d -= 2 * kPi;
  while (d < -kPi) d += 2 * kPi;
  return d;
}

bool circumcircle(Point2 a, Point2 b, Point2 c, Point2& centre, double& radius) {
  const double d = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
  if (std::abs(d) < 1e-18) return false;
  const double a2 = a.x * a.x + a.y * a.y, b2 = b.x * b.x + b.y * b.y, c2 = c.x * c.x + c.y * c.y;
  centre = {(a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d,
            (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d};
  radius = distance(a, centre);
  return true;
}

cl::IntPoint to_int(Point2 p) {
  return {static_cast<cl::cInt>(std::llround(p.x / material_check::kPolygonGrid)),
          static_cast<cl::cInt>(std::llround(p.y / material_check::kPolygonGrid))};
}

Point2 lerp(Point2 a, Point2 b, double t) { return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; }

// The pieces of a segment before and after fraction t.
std::pair<CurveSegment, CurveSegment> split(const CurveSegment& s, double t) {
  if (const auto* l = std::get_if<LineSegment>(&s)) {
    const Point2 m = lerp(l->a, l->b, t);
    return {LineSegment{l->a, m}, LineSegment{m, l->b}};
  }
  const auto& a = std::get<ArcSegment>(s);
  return {ArcSegment{a.centre, a.radius, a.start_angle, a.sweep * t},
          ArcSegment{a.centre, a.radius, a.start_angle + a.sweep * t, a.sweep * (1 - t)}};
}

bool degenerate(const CurveSegment& s) { return material_check::length_of(s) < 1e-7; }

}  // namespace

double distance(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

PlanarCurve curve_from_ring(const PolygonSet::Ring& ring) {
  PlanarCurve out;
  out.closed = true;
  const std::size_t n = ring.size();
  if (n < 3) return out;
  auto at = [&](std::size_t k) { return ring[k % n]; };
  // An arc run starting at vertex k: the vertices while each turn matches the first (Clipper's
  // round joins and discretised arcs turn evenly) and all lie on the circle through the run's
  // first, middle and last vertices.
  auto on_circle = [](Point2 p, Point2 centre, double radius) {
    return std::abs(distance(p, centre) - radius) <= 5e-5 + 1e-7 * radius;
  };
  // An arc run starting at vertex k: while each vertex turns as the first (Clipper's round joins
  // and discretised arcs turn evenly), at least three chords, all vertices on the circle through
  // the run's first, middle and last; then the vertices that still lie on it (a shorter last
  // chord).
  auto arc_run = [&](std::size_t k, std::size_t limit, ArcSegment& arc) -> std::size_t {
    if (limit < 3) return 0;
    const double t_ref = turn(at(k), at(k + 1), at(k + 2));
    if (std::abs(t_ref) < 1e-6 || std::abs(t_ref) > kPi / 4) return 0;
    std::size_t m = 2;
    while (m < limit && std::abs(turn(at(k + m - 1), at(k + m), at(k + m + 1)) - t_ref) <= 1e-3 * std::abs(t_ref) + 1e-7) ++m;
    if (m < 4) return 0;
    // The chords inside the run are equal (the first and last may be shorter).
    const double chord = distance(at(k + 1), at(k + 2));
    for (std::size_t j = 1; j + 1 < m; ++j) {
      if (std::abs(distance(at(k + j), at(k + j + 1)) - chord) > 0.01 * chord + 1e-6) return 0;
    }
    if (distance(at(k), at(k + 1)) > 1.01 * chord + 1e-6 || distance(at(k + m - 1), at(k + m)) > 1.01 * chord + 1e-6) return 0;
    Point2 centre;
    double radius;
    if (!circumcircle(at(k), at(k + m / 2), at(k + m), centre, radius) || radius > 1e3) return 0;
    for (std::size_t j = 0; j <= m; ++j) {
      if (!on_circle(at(k + j), centre, radius)) return 0;
    }
    while (m < limit) {
      const double t = turn(at(k + m - 1), at(k + m), at(k + m + 1));
      if (std::signbit(t) != std::signbit(t_ref) || std::abs(t) > std::abs(t_ref) + 1e-7 || !on_circle(at(k + m + 1), centre, radius)) break;
      ++m;
    }
    double sweep = 0;
    for (std::size_t j = 1; j <= m; ++j) {
      double d = std::atan2(at(k + j).y - centre.y, at(k + j).x - centre.x) -
                 std::atan2(at(k + j - 1).y - centre.y, at(k + j - 1).x - centre.x);
      while (d > kPi) d -= 2 * kPi;
      while (d < -kPi) d += 2 * kPi;
      sweep += d;
    }
    if ((sweep > 0) != (t_ref > 0)) return 0;
    arc = ArcSegment{centre, radius, std::atan2(at(k).y - centre.y, at(k).x - centre.x), sweep};
    return m;
  };
  // Start at a vertex where the turning changes (not inside an arc), so that no arc wraps.
  std::size_t start = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = turn(at(k + n - 1), at(k), at(k + 1)), b = turn(at(k), at(k + 1), at(k + 2));
    if (std::abs(a - b) > 1e-3 * std::max(std::abs(a), std::abs(b)) + 1e-7) {
      start = k;
      break;
    }
  }
  // A whole ring on one circle: a full circle.
  {
    Point2 centre;
    double radius;
    if (n >= 8 && circumcircle(at(0), at(n / 3), at(2 * n / 3), centre, radius)) {
      const double tol = 5e-5 + 1e-7 * radius;
      bool all = true;
      for (std::size_t k = 0; k < n && all; ++k) all = std::abs(distance(at(k), centre) - radius) <= tol;
      if (all && std::abs(turn(at(0), at(1), at(2))) < kPi / 4) {
        const double area = material_check::signed_area(ring);
        out.segments.emplace_back(ArcSegment{centre, radius, std::atan2(at(0).y - centre.y, at(0).x - centre.x),
                                             area > 0 ? 2 * kPi : -2 * kPi});
        return out;
      }
    }
  }
  std::size_t k = 0;
  while (k < n) {
    ArcSegment arc;
    const std::size_t m = arc_run(start + k, n - k, arc);
    if (m > 0) {
      out.segments.emplace_back(arc);
      k += m;
    } else {
      out.segments.emplace_back(LineSegment{at(start + k), at(start + k + 1)});
      ++k;
    }
  }
  return out;
}

std::vector<PlanarCurve> loops_of(const PolygonSet& region) {
  std::vector<PlanarCurve> out;
  for (const auto& ring : region.rings()) {
    auto c = curve_from_ring(ring);
    if (!c.segments.empty()) out.push_back(std::move(c));
  }
  return out;
}

CurvePlace closest_place(const PlanarCurve& curve, Point2 p) {
  CurvePlace best;
  best.distance = 1e300;
  for (std::size_t i = 0; i < curve.segments.size(); ++i) {
    const auto& s = curve.segments[i];
    double t = 0;
    Point2 q;
    if (const auto* l = std::get_if<LineSegment>(&s)) {
      const double dx = l->b.x - l->a.x, dy = l->b.y - l->a.y, L2 = dx * dx + dy * dy;
      t = L2 > 0 ? std::clamp(((p.x - l->a.x) * dx + (p.y - l->a.y) * dy) / L2, 0.0, 1.0) : 0;
      q = lerp(l->a, l->b, t);
    } else {
      const auto& a = std::get<ArcSegment>(s);
      double ang = std::atan2(p.y - a.centre.y, p.x - a.centre.x) - a.start_angle;
      const double sweep = std::abs(a.sweep);
      ang = a.sweep > 0 ? ang : -ang;
      ang = std::fmod(ang, 2 * kPi);
      if (ang < 0) ang += 2 * kPi;
      if (ang <= sweep) {
        t = sweep > 0 ? ang / sweep : 0;
      } else {  // beyond the arc: its nearer end
        t = distance(a.start(), p) <= distance(a.end(), p) ? 0 : 1;
      }
      q = a.at(t);
    }
    const double d = distance(p, q);
    if (d < best.distance) best = {i, t, q, d};
  }
  return best;
}

PlanarCurve loop_from(const PlanarCurve& loop, Point2 p) {
  if (loop.segments.empty()) return loop;
  const CurvePlace place = closest_place(loop, p);
  PlanarCurve out;
  out.closed = true;
  const std::size_t n = loop.segments.size();
  auto [before, after] = split(loop.segments[place.segment], place.fraction);
  if (!degenerate(after)) out.segments.push_back(after);
  for (std::size_t k = 1; k < n; ++k) out.segments.push_back(loop.segments[(place.segment + k) % n]);
  if (!degenerate(before)) out.segments.push_back(before);
  if (out.segments.empty()) out.segments.push_back(loop.segments[place.segment]);
  return out;
}

PlanarCurve curve_before(const PlanarCurve& curve, const CurvePlace& place) {
  PlanarCurve out;
  for (std::size_t k = 0; k < place.segment; ++k) out.segments.push_back(curve.segments[k]);
  auto [before, after] = split(curve.segments[place.segment], place.fraction);
  if (!degenerate(before)) out.segments.push_back(before);
  return out;
}

PlanarCurve curve_after(const PlanarCurve& curve, const CurvePlace& place) {
  PlanarCurve out;
  auto [before, after] = split(curve.segments[place.segment], place.fraction);
  if (!degenerate(after)) out.segments.push_back(after);
  for (std::size_t k = place.segment + 1; k < curve.segments.size(); ++k) out.segments.push_back(curve.segments[k]);
  return out;
}

PlanarCurve leading_part(const PlanarCurve& curve, double length) {
  PlanarCurve out;
  double left = length;
  for (const auto& s : curve.segments) {
    const double l = material_check::length_of(s);
    if (l <= left + 1e-12) {
      out.segments.push_back(s);
      left -= l;
      continue;
    }
    if (left > 1e-9) out.segments.push_back(split(s, left / l).first);
    break;
  }
  return out;
}

bool segment_inside(const PolygonSet& region, Point2 a, Point2 b) {
  if (distance(a, b) < 1e-9) return region.contains(a);
  cl::Clipper c;
  cl::Paths subject{{to_int(a), to_int(b)}};
  c.AddPaths(subject, cl::ptSubject, false);
  cl::Paths clip;
  for (const auto& r : region.rings()) {
    cl::Path p;
    for (const auto& q : r) p.push_back(to_int(q));
    clip.push_back(std::move(p));
  }
  c.AddPaths(clip, cl::ptClip, true);
  cl::PolyTree tree;
  c.Execute(cl::ctIntersection, tree, cl::pftNonZero, cl::pftNonZero);
  cl::Paths open;
  cl::OpenPathsFromPolyTree(tree, open);
  double inside = 0;
  for (const auto& p : open) {
    for (std::size_t k = 1; k < p.size(); ++k) {
      inside += std::hypot(static_cast<double>(p[k].X - p[k - 1].X), static_cast<double>(p[k].Y - p[k - 1].Y)) *
                material_check::kPolygonGrid;
    }
  }
  return inside >= distance(a, b) - 2e-4;
}

PolygonSet swept_by(const std::vector<PlanarCurve>& curves, double radius, bool square_ends) {
  cl::ClipperOffset o(2.0, kArcTolerance / material_check::kPolygonGrid);
  for (const auto& c : curves) {
    const auto pts = c.points(kArcTolerance);
    cl::Path p;
    for (const auto& q : pts) p.push_back(to_int(q));
    if (p.empty()) continue;
    if (p.size() == 1) p.push_back(p.front());
    o.AddPath(p, cl::jtRound, c.closed ? cl::etClosedLine : square_ends ? cl::etOpenButt : cl::etOpenRound);
  }
  cl::PolyTree tree;
  o.Execute(tree, radius / material_check::kPolygonGrid);
  std::vector<PolygonSet::Ring> rings;
  for (const cl::PolyNode* node = tree.GetFirst(); node; node = node->GetNext()) {
    PolygonSet::Ring r;
    for (const auto& q : node->Contour) {
      r.push_back({static_cast<double>(q.X) * material_check::kPolygonGrid, static_cast<double>(q.Y) * material_check::kPolygonGrid});
    }
    rings.push_back(std::move(r));
  }
  return PolygonSet::from_rings(std::move(rings));
}

}  // namespace ncbridge::toolpath_generator

namespace ncbridge::toolpath_generator {

std::vector<std::pair<Point2, Point2>> clip_segment(const PolygonSet& region, Point2 a, Point2 b) {
  namespace cl = ClipperLib;
  auto to_int = [](Point2 p) {
    return cl::IntPoint{static_cast<cl::cInt>(std::llround(p.x / material_check::kPolygonGrid)),
                        static_cast<cl::cInt>(std::llround(p.y / material_check::kPolygonGrid))};
  };
  cl::Clipper c;
  cl::Paths subject{{to_int(a), to_int(b)}};
  c.AddPaths(subject, cl::ptSubject, false);
  cl::Paths clip;
  for (const auto& r : region.rings()) {
    cl::Path p;
    for (const auto& q : r) p.push_back(to_int(q));
    clip.push_back(std::move(p));
  }
  c.AddPaths(clip, cl::ptClip, true);
  cl::PolyTree tree;
  c.Execute(cl::ctIntersection, tree, cl::pftNonZero, cl::pftNonZero);
  cl::Paths open;
  cl::OpenPathsFromPolyTree(tree, open);
  const double dx = b.x - a.x, dy = b.y - a.y, L2 = dx * dx + dy * dy;
  auto along = [&](Point2 p) { return L2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / L2 : 0.0; };
  std::vector<std::pair<Point2, Point2>> out;
  for (const auto& p : open) {
    if (p.size() < 2) continue;
    Point2 s{static_cast<double>(p.front().X) * material_check::kPolygonGrid, static_cast<double>(p.front().Y) * material_check::kPolygonGrid};
    Point2 e{static_cast<double>(p.back().X) * material_check::kPolygonGrid, static_cast<double>(p.back().Y) * material_check::kPolygonGrid};
    if (along(s) > along(e)) std::swap(s, e);
    // Back onto the exact line (the grid moved them by up to 10 nm).
    const double ts = along(s), te = along(e);
    s = {a.x + dx * ts, a.y + dy * ts};
    e = {a.x + dx * te, a.y + dy * te};
    if (distance(s, e) > 1e-6) out.emplace_back(s, e);
  }
  std::sort(out.begin(), out.end(), [&](const auto& x, const auto& y) { return along(x.first) < along(y.first); });
  return out;
}

PolygonSet without_slivers(const PolygonSet& region, double width) {
  if (region.empty()) return region;
  return region.offset(-width / 2, kArcTolerance).offset(width / 2, kArcTolerance);
}

}  // namespace ncbridge::toolpath_generator
