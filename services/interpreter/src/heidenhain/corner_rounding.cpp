#include "heidenhain/corner_rounding.hpp"

#include <cmath>
#include <optional>
#include <vector>

namespace ncbridge::interpreter::heidenhain {

using lowering::Point3;

namespace {

constexpr double kEps = 1e-9;

struct Vec {
  double x = 0, y = 0;
};

Vec unit(double x, double y) {
  const double l = std::hypot(x, y);
  return l < kEps ? Vec{} : Vec{x / l, y / l};
}

// Direction of travel of an element at a point on it.
Vec tangent_at(const ContourElement& e, const Point3& p) {
  if (!e.arc) return unit(e.end.x - e.start.x, e.end.y - e.start.y);
  const Vec r = unit(p.x - e.cx, p.y - e.cy);
  return e.cw ? Vec{r.y, -r.x} : Vec{-r.y, r.x};
}

// The element moved sideways by `distance` to the side `side` (+1 left of travel, -1 right):
// a line (point, direction) or a circle (centre, radius).
struct Offset {
  bool circle = false;
  Vec p, d;        // line
  double radius = 0;
};

Offset offset_of(const ContourElement& e, const Point3& corner, int side, double distance) {
  Offset o;
  if (!e.arc) {
    const Vec d = tangent_at(e, corner);
    o.d = d;
    o.p = {corner.x - d.y * side * distance, corner.y + d.x * side * distance};
    return o;
  }
  o.circle = true;
  o.p = {e.cx, e.cy};
  const double r = std::hypot(corner.x - e.cx, corner.y - e.cy);
  // left of travel points to the centre on a counter-clockwise arc
  const bool towards_centre = (side > 0) != e.cw;
  o.radius = towards_centre ? r - distance : r + distance;
  return o;
}

std::vector<Vec> intersect(const Offset& a, const Offset& b) {
  std::vector<Vec> out;
  if (!a.circle && !b.circle) {
    const double den = a.d.x * b.d.y - a.d.y * b.d.x;
    if (std::fabs(den) < kEps) return out;
    const double t = ((b.p.x - a.p.x) * b.d.y - (b.p.y - a.p.y) * b.d.x) / den;
    out.push_back({a.p.x + a.d.x * t, a.p.y + a.d.y * t});
    return out;
  }
  if (!a.circle || !b.circle) {
    const Offset& line = a.circle ? b : a;
    const Offset& circle = a.circle ? a : b;
    const double fx = line.p.x - circle.p.x, fy = line.p.y - circle.p.y;
    const double bq = fx * line.d.x + fy * line.d.y;
    const double c = fx * fx + fy * fy - circle.radius * circle.radius;
    double disc = bq * bq - c;
    if (disc < -kEps) return out;
    disc = std::sqrt(std::max(0.0, disc));
    for (double t : {-bq - disc, -bq + disc}) out.push_back({line.p.x + line.d.x * t, line.p.y + line.d.y * t});
    return out;
  }
  const double dx = b.p.x - a.p.x, dy = b.p.y - a.p.y;
  const double d = std::hypot(dx, dy);
  if (d < kEps) return out;
  const double along = (a.radius * a.radius - b.radius * b.radius + d * d) / (2 * d);
  double h2 = a.radius * a.radius - along * along;
  if (h2 < -kEps) return out;
  const double h = std::sqrt(std::max(0.0, h2));
  const double mx = a.p.x + dx * along / d, my = a.p.y + dy * along / d;
  out.push_back({mx - dy * h / d, my + dx * h / d});
  out.push_back({mx + dy * h / d, my - dx * h / d});
  return out;
}

// The point of the element nearest to `p` (the foot of the perpendicular, or on the circle).
Point3 foot(const ContourElement& e, const Vec& p, double z) {
  if (!e.arc) {
    const Vec d = unit(e.end.x - e.start.x, e.end.y - e.start.y);
    const double t = (p.x - e.start.x) * d.x + (p.y - e.start.y) * d.y;
    return {e.start.x + d.x * t, e.start.y + d.y * t, z};
  }
  const double r = std::hypot(e.end.x - e.cx, e.end.y - e.cy);
  const Vec u = unit(p.x - e.cx, p.y - e.cy);
  return {e.cx + u.x * r, e.cy + u.y * r, z};
}

// Whether `p` lies on the element between its start and its end (arcs: within the swept angle).
bool on_element(const ContourElement& e, const Point3& p) {
  if (!e.arc) {
    const double len = std::hypot(e.end.x - e.start.x, e.end.y - e.start.y);
    const Vec d = unit(e.end.x - e.start.x, e.end.y - e.start.y);
    const double t = (p.x - e.start.x) * d.x + (p.y - e.start.y) * d.y;
    return t >= -1e-7 && t <= len + 1e-7;
  }
  auto angle_from_start = [&](const Point3& q) {
    const double a0 = std::atan2(e.start.y - e.cy, e.start.x - e.cx);
    const double a = std::atan2(q.y - e.cy, q.x - e.cx);
    double sweep = e.cw ? a0 - a : a - a0;
    while (sweep < -1e-9) sweep += 2 * std::numbers::pi;
    return sweep;
  };
  double total = angle_from_start(e.end);
  if (total < 1e-9) total = 2 * std::numbers::pi;  // a full circle
  return angle_from_start(p) <= total + 1e-7;
}

}  // namespace

RoundedCorner round_corner(const ContourElement& before, const ContourElement& after, double radius) {
  RoundedCorner result;
  const Point3& corner = before.end;
  const Vec t_in = tangent_at(before, corner);
  const Vec t_out = tangent_at(after, corner);
  const double cross = t_in.x * t_out.y - t_in.y * t_out.x;
  const double dot = t_in.x * t_out.x + t_in.y * t_out.y;
  if (std::fabs(cross) < 1e-9 && dot > 0) {
    result.error = "RND at a corner without a change of direction (the elements are tangent)";
    return result;
  }
  if (std::fabs(cross) < 1e-9) {
    result.error = "RND at a corner where the contour turns back on itself";
    return result;
  }
  const int side = cross > 0 ? 1 : -1;  // the rounding arc lies inside the turn
  const Offset a = offset_of(before, corner, side, radius);
  const Offset b = offset_of(after, corner, side, radius);
  if ((a.circle && a.radius <= kEps) || (b.circle && b.radius <= kEps)) {
    result.error = "RND radius is not smaller than the radius of the arc it rounds";
    return result;
  }
  std::optional<Vec> centre;
  double best = 0;
  for (const Vec& c : intersect(a, b)) {
    const double d = std::hypot(c.x - corner.x, c.y - corner.y);
    if (!centre || d < best) {
      centre = c;
      best = d;
    }
  }
  if (!centre) {
    result.error = "RND: no arc of this radius touches both elements";
    return result;
  }
  result.t1 = foot(before, *centre, corner.z);
  result.t2 = foot(after, *centre, corner.z);
  if (!on_element(before, result.t1) || !on_element(after, result.t2)) {
    result.error = "RND too large for the elements it joins";
    return result;
  }
  result.centre = {centre->x, centre->y, corner.z};
  result.ccw = side > 0;
  result.ok = true;
  return result;
}

bool radius_arc_centre(const Point3& start, const Point3& end, double radius, bool cw, double& cx, double& cy) {
  const double r = std::fabs(radius);
  const double dx = end.x - start.x, dy = end.y - start.y;
  const double chord = std::hypot(dx, dy);
  if (chord < 1e-9 || chord > 2 * r + 1e-6) return false;
  const double h = std::sqrt(std::max(0.0, r * r - chord * chord / 4));
  const double mx = (start.x + end.x) / 2, my = (start.y + end.y) / 2;
  // R+ : the shorter arc (< 180 degrees); R- : the longer. The centre lies right of the chord
  // for a short clockwise arc.
  const bool right = cw == (radius > 0);
  double nx = dy / chord, ny = -dx / chord;  // right-hand normal of the chord
  if (!right) {
    nx = -nx;
    ny = -ny;
  }
  cx = mx + nx * h;
  cy = my + ny * h;
  return true;
}

}  // namespace ncbridge::interpreter::heidenhain
