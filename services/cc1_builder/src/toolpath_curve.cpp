#include "toolpath_curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace ncbridge::cc1_builder {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kLengthEpsilon = 1e-9;   // mm: below this two coordinates are the same
constexpr std::size_t kMaxHelixPoints = 100000;

void append_point(stepnc::CompositeCurve& curve, const stepnc::CartesianPoint& from,
                  const stepnc::CartesianPoint& to) {
  if (!curve.segments.empty()) {
    if (auto* line = std::get_if<stepnc::Polyline>(&curve.segments.back())) {
      line->points.push_back(to);
      return;
    }
  }
  curve.segments.emplace_back(stepnc::Polyline{{from, to}});
}

double degrees(double radians) { return radians * 180.0 / kPi; }

// Parameter of a point reached after travelling `travelled` radians from the trim start, on a
// circle whose parameter 0 is the start: counter-clockwise adds, clockwise subtracts.
double parameter_after(double travelled, bool ccw) {
  double p = std::fmod(degrees(ccw ? travelled : -travelled), 360.0);
  if (p < 0) p += 360.0;
  if (p >= 360.0) p -= 360.0;
  return p == 0 ? 0.0 : p;  // no -0 (a clockwise start) in the file
}

}  // namespace

PlaneAxes axes_of(canonical::Plane plane) {
  switch (plane) {
    case canonical::Plane::YZ: case canonical::Plane::VW: return {1, 2, 0};
    case canonical::Plane::XZ: case canonical::Plane::UW: return {2, 0, 1};
    case canonical::Plane::XY: case canonical::Plane::UV: break;
  }
  return {0, 1, 2};
}

double get(const stepnc::CartesianPoint& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

void set(stepnc::CartesianPoint& p, int axis, double value) {
  (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = value;
}

stepnc::Direction unit_axis(int axis, double sign) {
  stepnc::Direction d{0, 0, 0};
  (axis == 0 ? d.x : axis == 1 ? d.y : d.z) = sign < 0 ? -1.0 : 1.0;
  return d;
}

void append_line(stepnc::CompositeCurve& curve, const stepnc::CartesianPoint& from,
                 const stepnc::CartesianPoint& to) {
  if (from == to) return;
  append_point(curve, from, to);
}

bool append_arc(stepnc::CompositeCurve& curve, const stepnc::CartesianPoint& from,
                const stepnc::CartesianPoint& to, double centre_first, double centre_second,
                PlaneAxes axes, int rotation, double chord_tolerance) {
  const bool ccw = rotation >= 0;
  const int turns = std::max(1, std::abs(rotation));
  const double s1 = get(from, axes.first) - centre_first, s2 = get(from, axes.second) - centre_second;
  const double e1 = get(to, axes.first) - centre_first, e2 = get(to, axes.second) - centre_second;
  const double radius = std::hypot(s1, s2);
  if (radius < kLengthEpsilon) {  // degenerate: nothing to turn about
    append_line(curve, from, to);
    return true;
  }
  const double a0 = std::atan2(s2, s1);
  const double a1 = std::atan2(e2, e1);
  double sweep = ccw ? a1 - a0 : a0 - a1;
  while (sweep <= 1e-12) sweep += 2 * kPi;
  while (sweep > 2 * kPi + 1e-12) sweep -= 2 * kPi;
  sweep += 2 * kPi * (turns - 1);

  const double rise = get(to, axes.normal) - get(from, axes.normal);
  const double u1 = s1 / radius, u2 = s2 / radius;  // reference direction (towards the start)
  auto point_at = [&](double travelled, double height) {
    const double phi = ccw ? travelled : -travelled;
    const double c = std::cos(phi), s = std::sin(phi);
    stepnc::CartesianPoint p;
    set(p, axes.first, centre_first + radius * (u1 * c - u2 * s));
    set(p, axes.second, centre_second + radius * (u2 * c + u1 * s));
    set(p, axes.normal, height);
    return p;
  };

  if (std::abs(rise) > kLengthEpsilon) {
    // A helix has no exact Part 42 form in the schema's subset: a polyline within the tolerance.
    const double tol = std::max(chord_tolerance, 1e-6);
    const double step = tol < radius ? 2 * std::acos(1 - tol / radius) : sweep;
    const std::size_t n = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(sweep / step)), 1, kMaxHelixPoints);
    stepnc::CartesianPoint previous = from;
    for (std::size_t i = 1; i <= n; ++i) {
      const double f = static_cast<double>(i) / static_cast<double>(n);
      const stepnc::CartesianPoint p = i == n ? to : point_at(sweep * f, get(from, axes.normal) + rise * f);
      append_point(curve, previous, p);
      previous = p;
    }
    return false;
  }

  stepnc::Axis2Placement3d position;
  set(position.location, axes.first, centre_first);
  set(position.location, axes.second, centre_second);
  set(position.location, axes.normal, get(from, axes.normal));
  position.axis = unit_axis(axes.normal);
  position.ref_direction = stepnc::Direction{0, 0, 0};
  {
    stepnc::CartesianPoint r;
    set(r, axes.first, u1);
    set(r, axes.second, u2);
    set(r, axes.normal, 0);
    position.ref_direction = stepnc::Direction{r.x, r.y, r.z};
  }
  // A trimmed circle of (nearly) a whole turn has ambiguous trims: split into half turns.
  const std::size_t pieces = sweep >= 2 * kPi - 1e-9 ? static_cast<std::size_t>(std::ceil(sweep / kPi - 1e-9)) : 1;
  stepnc::CartesianPoint start = from;
  for (std::size_t i = 0; i < pieces; ++i) {
    const double t0 = sweep * static_cast<double>(i) / static_cast<double>(pieces);
    const double t1 = sweep * static_cast<double>(i + 1) / static_cast<double>(pieces);
    const stepnc::CartesianPoint end = i + 1 == pieces ? to : point_at(t1, get(from, axes.normal));
    stepnc::TrimmedCircle arc;
    arc.position = position;
    arc.radius = radius;
    arc.trim_1_point = start;
    arc.trim_1_parameter = parameter_after(t0, ccw);
    arc.trim_2_point = end;
    arc.trim_2_parameter = parameter_after(t1, ccw);
    arc.sense_agreement = ccw;
    curve.segments.emplace_back(arc);
    start = end;
  }
  return true;
}

double lowest_z(const stepnc::TrimmedCircle& arc) {
  const double ends = std::min(arc.trim_1_point.z, arc.trim_2_point.z);
  const auto& u = arc.position.ref_direction;
  const auto& n = arc.position.axis;
  const stepnc::Direction v{n.y * u.z - n.z * u.y, n.z * u.x - n.x * u.z, n.x * u.y - n.y * u.x};
  // Direction of -Z within the circle's plane, as an angle from the reference direction.
  const double du = -u.z, dv = -v.z;
  if (std::hypot(du, dv) < 1e-12) return ends;  // circle parallel to XY
  double angle = degrees(std::atan2(dv, du));
  double travelled = arc.sense_agreement ? angle - arc.trim_1_parameter : arc.trim_1_parameter - angle;
  travelled = std::fmod(travelled, 360.0);
  if (travelled < 0) travelled += 360.0;
  if (travelled > stepnc::sweep_degrees(arc)) return ends;
  return std::min(ends, arc.position.location.z - arc.radius * std::hypot(du, dv));
}

stepnc::BSplineCurve nurbs_curve(const std::vector<stepnc::CartesianPoint>& control_points,
                                 const std::vector<double>& weights, int order) {
  const auto count = static_cast<long long>(control_points.size());
  if (order < 2 || count < order || weights.size() != control_points.size()) {
    throw std::invalid_argument("a NURBS of order " + std::to_string(order) + " needs at least " +
                                std::to_string(std::max(order, 2)) + " control points with a weight each, not " +
                                std::to_string(count));
  }
  stepnc::BSplineCurve c;
  c.degree = order - 1;
  c.control_points = control_points;
  // LinuxCNC's knots (knot_vector_creator): `order` zeros, 1 .. n - order + 1 once each, then
  // `order` times n - order + 2, for control points 0..n.
  const long long last = count - order + 1;
  for (long long k = 0; k <= last; ++k) {
    c.knots.push_back(static_cast<double>(k));
    c.knot_multiplicities.push_back(k == 0 || k == last ? order : 1);
  }
  c.knot_spec = last == 1 ? stepnc::KnotType::PiecewiseBezierKnots : stepnc::KnotType::QuasiUniformKnots;
  if (std::any_of(weights.begin(), weights.end(), [&](double w) { return w != weights.front(); })) c.weights = weights;
  if (const std::string problem = stepnc::bspline_problem(c); !problem.empty()) {
    throw std::invalid_argument("a NURBS that is no B-spline: " + problem);
  }
  return c;
}

void append_bspline(stepnc::CompositeCurve& curve, stepnc::BSplineCurve spline) {
  curve.segments.emplace_back(std::move(spline));
}

}  // namespace ncbridge::cc1_builder
