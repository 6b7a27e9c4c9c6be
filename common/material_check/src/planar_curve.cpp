#include "ncbridge/material_check/planar_curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncbridge::material_check {

namespace {
constexpr double kPi = std::numbers::pi;
}

Point2 ArcSegment::at(double fraction) const {
  const double a = start_angle + sweep * fraction;
  return {centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)};
}
Point2 ArcSegment::start() const { return at(0); }
Point2 ArcSegment::end() const { return at(1); }

Point2 start_of(const CurveSegment& s) {
  if (const auto* l = std::get_if<LineSegment>(&s)) return l->a;
  return std::get<ArcSegment>(s).start();
}

Point2 end_of(const CurveSegment& s) {
  if (const auto* l = std::get_if<LineSegment>(&s)) return l->b;
  return std::get<ArcSegment>(s).end();
}

double length_of(const CurveSegment& s) {
  if (const auto* l = std::get_if<LineSegment>(&s)) return std::hypot(l->b.x - l->a.x, l->b.y - l->a.y);
  const auto& a = std::get<ArcSegment>(s);
  return a.radius * std::abs(a.sweep);
}

double PlanarCurve::length() const {
  double sum = 0;
  for (const auto& s : segments) sum += length_of(s);
  return sum;
}

std::vector<Point2> PlanarCurve::points(double chord_tolerance) const {
  std::vector<Point2> out;
  auto push = [&](Point2 p) {
    if (out.empty() || std::hypot(p.x - out.back().x, p.y - out.back().y) > 1e-9) out.push_back(p);
  };
  for (const auto& s : segments) {
    if (const auto* l = std::get_if<LineSegment>(&s)) {
      push(l->a);
      push(l->b);
      continue;
    }
    const auto& a = std::get<ArcSegment>(s);
    const double tol = std::max(chord_tolerance, 1e-9);
    const double step = tol < a.radius ? 2 * std::acos(1 - tol / a.radius) : kPi / 2;
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(a.sweep) / step)));
    for (int k = 0; k <= n; ++k) push(a.at(static_cast<double>(k) / n));
  }
  if (closed && out.size() > 1 && std::hypot(out.front().x - out.back().x, out.front().y - out.back().y) <= 1e-9) {
    out.pop_back();
  }
  return out;
}

double PlanarCurve::signed_area() const {
  // Green's theorem: lines by the shoelace term, arcs by their exact integral of x dy - y dx.
  double twice = 0;
  for (const auto& s : segments) {
    if (const auto* l = std::get_if<LineSegment>(&s)) {
      twice += l->a.x * l->b.y - l->b.x * l->a.y;
      continue;
    }
    const auto& a = std::get<ArcSegment>(s);
    const double t0 = a.start_angle, t1 = a.start_angle + a.sweep;
    const double cx = a.centre.x, cy = a.centre.y, r = a.radius;
    // integral of (x dy - y dx) with x = cx + r cos t, y = cy + r sin t
    twice += r * r * (t1 - t0) + cx * r * (std::sin(t1) - std::sin(t0)) + cy * r * (std::cos(t0) - std::cos(t1));
  }
  return twice;
}

PlanarCurve PlanarCurve::reversed() const {
  PlanarCurve out;
  out.closed = closed;
  for (auto it = segments.rbegin(); it != segments.rend(); ++it) {
    if (const auto* l = std::get_if<LineSegment>(&*it)) {
      out.segments.emplace_back(LineSegment{l->b, l->a});
    } else {
      const auto& a = std::get<ArcSegment>(*it);
      out.segments.emplace_back(ArcSegment{a.centre, a.radius, a.start_angle + a.sweep, -a.sweep});
    }
  }
  return out;
}

PlanarCurve rounded_rectangle(Point2 centre, double length, double width, double corner_radius, double angle) {
  const double r = std::clamp(corner_radius, 0.0, std::min(length, width) / 2);
  const double hl = length / 2, hw = width / 2;
  const double c = std::cos(angle), s = std::sin(angle);
  auto place = [&](double u, double v) { return Point2{centre.x + u * c - v * s, centre.y + u * s + v * c}; };
  PlanarCurve out;
  out.closed = true;
  // Counter-clockwise from the middle of the -v side: corners at (+,-), (+,+), (-,+), (-,-).
  const double corners[4][2] = {{hl, -hw}, {hl, hw}, {-hl, hw}, {-hl, -hw}};
  const double dirs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};  // travel along the side ending at each corner
  Point2 at = place(r > 0 ? -hl + r : -hl, -hw);
  for (int k = 0; k < 4; ++k) {
    const double ux = dirs[k][0], uy = dirs[k][1];
    const Point2 before = place(corners[k][0] - ux * r, corners[k][1] - uy * r);
    if (std::hypot(before.x - at.x, before.y - at.y) > 1e-12) out.segments.emplace_back(LineSegment{at, before});
    if (r > 0) {
      // The corner's centre lies r inside both sides; the arc turns 90 degrees counter-clockwise.
      const double nx = -uy, ny = ux;  // inward normal of the side (left of travel)
      const Point2 cc = place(corners[k][0] - ux * r + nx * r, corners[k][1] - uy * r + ny * r);
      const double start = std::atan2(-ny, -nx) + angle;
      out.segments.emplace_back(ArcSegment{cc, r, start, kPi / 2});
      at = end_of(out.segments.back());
    } else {
      at = before;
    }
  }
  const Point2 first = start_of(out.segments.front());
  if (std::hypot(first.x - at.x, first.y - at.y) > 1e-12) out.segments.emplace_back(LineSegment{at, first});
  return out;
}

PlanarCurve circle(Point2 centre, double radius) {
  PlanarCurve out;
  out.closed = true;
  out.segments.emplace_back(ArcSegment{centre, radius, 0, 2 * kPi});
  return out;
}

}  // namespace ncbridge::material_check
