#include "cc1_toolpath.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncbridge::toolpath_generator {

namespace {

namespace sn = stepnc;
constexpr double kPi = std::numbers::pi;
constexpr double kHelixChord = 0.001;

// Coordinates to 1e-6 mm, as the recogniser writes features: files show 70. rather than 69.9999999.
double tidy(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0 ? 0 : r;
}

sn::CartesianPoint cp(const Point3& p) { return {tidy(p.x), tidy(p.y), tidy(p.z)}; }

void line_to(sn::CompositeCurve& curve, const Point3& from, const Point3& to) {
  const sn::CartesianPoint a = cp(from), b = cp(to);
  if (a == b) return;
  if (!curve.segments.empty()) {
    if (auto* l = std::get_if<sn::Polyline>(&curve.segments.back())) {
      l->points.push_back(b);
      return;
    }
  }
  curve.segments.emplace_back(sn::Polyline{{a, b}});
}

double degrees(double radians) { return radians * 180 / kPi; }

void arc_to(sn::CompositeCurve& curve, const Point3& from, const Move3& m) {
  const Point2 c = *m.arc_centre;
  const double radius = std::hypot(from.x - c.x, from.y - c.y);
  const double start = std::atan2(from.y - c.y, from.x - c.x);
  if (radius < 1e-9) {
    line_to(curve, from, m.end);
    return;
  }
  if (std::abs(m.end.z - from.z) > 1e-9) {  // a helix: chords within the tolerance
    // Each chord also descends at least 0.002 mm: a reader that takes moves within 0.001 mm
    // of one height as a level must not find levels along a ramp.
    const double step = kHelixChord < radius ? 2 * std::acos(1 - kHelixChord / radius) : kPi / 2;
    const int by_drop = static_cast<int>(std::floor(std::abs(m.end.z - from.z) / 0.002));
    const int n = std::max(1, std::min(static_cast<int>(std::ceil(std::abs(m.arc_sweep) / step)), by_drop));
    Point3 prev = from;
    for (int k = 1; k <= n; ++k) {
      const double f = static_cast<double>(k) / n, a = start + m.arc_sweep * f;
      const Point3 q = k == n ? m.end : Point3{c.x + radius * std::cos(a), c.y + radius * std::sin(a), from.z + (m.end.z - from.z) * f};
      line_to(curve, prev, q);
      prev = q;
    }
    return;
  }
  // At most half a turn per trimmed curve (the trims of a whole turn are ambiguous).
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(m.arc_sweep) / kPi - 1e-9)));
  const bool ccw = m.arc_sweep > 0;
  for (int k = 0; k < pieces; ++k) {
    const double a0 = start + m.arc_sweep * k / pieces, a1 = start + m.arc_sweep * (k + 1) / pieces;
    const Point3 p0 = k == 0 ? from : Point3{c.x + radius * std::cos(a0), c.y + radius * std::sin(a0), from.z};
    const Point3 p1 = k + 1 == pieces ? m.end : Point3{c.x + radius * std::cos(a1), c.y + radius * std::sin(a1), from.z};
    sn::TrimmedCircle arc;
    arc.position.location = {tidy(c.x), tidy(c.y), tidy(from.z)};
    arc.position.axis = {0, 0, 1};
    arc.position.ref_direction = {tidy(std::cos(a0)), tidy(std::sin(a0)), 0};
    arc.radius = tidy(radius);
    arc.trim_1_point = cp(p0);
    arc.trim_1_parameter = 0;
    arc.trim_2_point = cp(p1);
    double p = degrees(std::abs(m.arc_sweep) / pieces);
    if (!ccw) p = 360 - p;
    arc.trim_2_parameter = tidy(std::fmod(p, 360.0));
    arc.sense_agreement = ccw;
    curve.segments.emplace_back(arc);
  }
}

}  // namespace

sn::ToolpathList toolpath_list(const Motion3& motion, std::optional<sn::TechnologyRef> entry_technology) {
  sn::ToolpathList list;
  Point3 at = motion.start;
  std::optional<Move3::Kind> kind;
  for (const auto& m : motion.moves) {
    if (!kind || *kind != m.kind) {
      sn::CutterLocationTrajectory t;
      t.its_type = m.kind == Move3::Kind::Rapid ? sn::ToolpathType::Connect : sn::ToolpathType::TrajectoryPath;
      if (m.kind == Move3::Kind::Entry && entry_technology) t.its_technology = entry_technology;
      list.its_list.push_back(std::move(t));
      kind = m.kind;
    }
    auto& curve = list.its_list.back().basiccurve;
    if (m.arc_centre) arc_to(curve, at, m);
    else line_to(curve, at, m.end);
    at = m.end;
  }
  auto& l = list.its_list;
  l.erase(std::remove_if(l.begin(), l.end(), [](const auto& t) { return t.basiccurve.segments.empty(); }), l.end());
  return list;
}

sn::ToolpathList rapid_list(const std::vector<Point3>& points) {
  sn::CutterLocationTrajectory t;
  t.its_type = sn::ToolpathType::Connect;
  sn::Polyline line;
  for (const auto& p : points) {
    const auto q = cp(p);
    if (line.points.empty() || !(line.points.back() == q)) line.points.push_back(q);
  }
  if (line.points.size() >= 2) t.basiccurve.segments.emplace_back(std::move(line));
  sn::ToolpathList list;
  if (!t.basiccurve.segments.empty()) list.its_list.push_back(std::move(t));
  return list;
}

}  // namespace ncbridge::toolpath_generator
