#include "ncbridge/toolpath_optimizer/geometry.hpp"

#include <algorithm>

namespace ncbridge::toolpath_optimizer {

Vec3 from_plane(PlanePoint p, canonical::Plane plane) {
  switch (plane) {
    case canonical::Plane::YZ: return {p.normal, p.first, p.second};
    case canonical::Plane::XZ: return {p.second, p.normal, p.first};
    default: return {p.first, p.second, p.normal};
  }
}

double distance_to_segment(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 d = b - a;
  const double len2 = dot(d, d);
  if (len2 <= 0) return distance(p, a);
  const double t = std::clamp(dot(p - a, d) / len2, 0.0, 1.0);
  return distance(p, a + t * d);
}

double sweep_between(double a0, double a1, bool ccw) {
  double s = a1 - a0;
  if (ccw) {
    while (s <= 0) s += 2 * kPi;
    while (s > 2 * kPi) s -= 2 * kPi;
  } else {
    while (s >= 0) s -= 2 * kPi;
    while (s < -2 * kPi) s += 2 * kPi;
  }
  return s;
}

ArcPath resolve_arc(const Motion& m) {
  ArcPath a;
  a.plane = m.arc.plane;
  a.centre_first = m.arc.first_centre;
  a.centre_second = m.arc.second_centre;
  const PlanePoint s = to_plane(m.start, a.plane);
  const PlanePoint e = to_plane(m.end, a.plane);
  a.start_radius = std::hypot(s.first - a.centre_first, s.second - a.centre_second);
  a.end_radius = std::hypot(e.first - a.centre_first, e.second - a.centre_second);
  a.start_angle = std::atan2(s.second - a.centre_second, s.first - a.centre_first);
  const double end_angle = std::atan2(e.second - a.centre_second, e.first - a.centre_first);
  // The same point in the plane (to a controller's resolution): a full circle.
  const bool closed = std::hypot(e.first - s.first, e.second - s.second) <= 1e-9 * std::max(1.0, a.start_radius);
  a.sweep = closed ? (m.arc.ccw ? 2 * kPi : -2 * kPi) : sweep_between(a.start_angle, end_angle, m.arc.ccw);
  a.sweep += (m.arc.ccw ? 2 * kPi : -2 * kPi) * m.arc.extra_turns;
  a.start_normal = s.normal;
  a.end_normal = e.normal;
  return a;
}

Vec3 ArcPath::at(double f) const {
  const double angle = start_angle + f * sweep;
  const double r = start_radius + f * (end_radius - start_radius);
  return from_plane({centre_first + r * std::cos(angle), centre_second + r * std::sin(angle),
                     start_normal + f * (end_normal - start_normal)},
                    plane);
}

double ArcPath::length() const {
  const double planar = std::abs(sweep) * 0.5 * (start_radius + end_radius);
  return std::hypot(planar, end_normal - start_normal);
}

double path_length(const Motion& m) {
  if (m.kind == MotionKind::Arc) return resolve_arc(m).length();
  return distance(m.start, m.end);
}

}  // namespace ncbridge::toolpath_optimizer
