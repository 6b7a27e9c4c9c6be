#include "feature_entities.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "feature_geometry.hpp"

namespace ncbridge::process_planner {

namespace pr = part_reader;
namespace sn = stepnc;

namespace {

// A B-rep gives no tolerances: its sizes get +/- 0.1 mm, as the CC1 holes from programs.
constexpr double kTolerance = 0.1;

double tidy(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0 ? 0 : r;
}

sn::TolerancedLengthMeasure toleranced(double size, const std::optional<std::pair<double, double>>& tolerance = std::nullopt) {
  sn::TolerancedLengthMeasure m{std::max(tidy(size), 1e-3), kTolerance, kTolerance, 3};
  if (tolerance) {
    m.upper_limit = tidy(std::abs(tolerance->first));
    m.lower_limit = tidy(std::abs(tolerance->second));
    m.significant_digits = 4;
  }
  return m;
}

sn::Axis2Placement3d placement_at(const LocalFrame& f, double lx, double ly, double x_cos, double x_sin) {
  const XY o = f.to_world(lx, ly);
  const double cx = f.cx * x_cos - f.sx * x_sin, sx = f.sx * x_cos + f.cx * x_sin;
  return {{tidy(o.x), tidy(o.y), tidy(f.oz)}, {0, 0, 1}, {tidy(cx), tidy(sx), 0}};
}

sn::Plane depth_plane(double depth) { return {{{0, 0, -tidy(depth)}, {0, 0, 1}, {1, 0, 0}}}; }

double degrees(double radians) {
  double d = radians * 180 / std::numbers::pi;
  if (d < 0) d += 360;
  if (d >= 360) d -= 360;
  return tidy(d);
}

// An open run of outline edges [first, first + count) as a composite curve.
sn::CompositeCurve run_curve(const std::vector<pr::OutlineVertex>& outline, std::size_t first, std::size_t count) {
  sn::CompositeCurve curve;
  sn::Polyline line;
  const std::size_t n = outline.size();
  auto flush = [&]() {
    if (line.points.size() >= 2) curve.segments.emplace_back(line);
    line.points.clear();
  };
  for (std::size_t k = 0; k < count; ++k) {
    const auto& a = outline[(first + k) % n];
    const auto& b = outline[(first + k + 1) % n];
    const sn::CartesianPoint pa{tidy(a.x), tidy(a.y), 0}, pb{tidy(b.x), tidy(b.y), 0};
    if (a.bulge == 0) {
      if (line.points.empty()) line.points.push_back(pa);
      line.points.push_back(pb);
      continue;
    }
    flush();
    const double chord = std::hypot(b.x - a.x, b.y - a.y);
    const double d = chord * (1 - a.bulge * a.bulge) / (4 * a.bulge);
    const double cx = (a.x + b.x) / 2 - (b.y - a.y) / chord * d, cy = (a.y + b.y) / 2 + (b.x - a.x) / chord * d;
    sn::TrimmedCircle arc;
    arc.position = {{tidy(cx), tidy(cy), 0}, {0, 0, 1}, {1, 0, 0}};
    arc.radius = tidy(std::hypot(a.x - cx, a.y - cy));
    arc.trim_1_point = pa;
    arc.trim_1_parameter = degrees(std::atan2(a.y - cy, a.x - cx));
    arc.trim_2_point = pb;
    arc.trim_2_parameter = degrees(std::atan2(b.y - cy, b.x - cx));
    arc.sense_agreement = a.bulge > 0;
    curve.segments.emplace_back(arc);
  }
  flush();
  return curve;
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

sn::Feature round_hole(const pr::Feature& f, const std::string& id) {
  sn::RoundHole h;
  h.its_id = id;
  h.feature_placement = placement_at(frame_of(f), 0, 0, 1, 0);
  h.depth = depth_plane(f.depth);
  h.diameter = toleranced(f.diameter, f.diameter_tolerance);
  switch (f.bottom) {
    case pr::HoleBottom::Through: h.bottom_condition = sn::ThroughBottomCondition{}; break;
    case pr::HoleBottom::Conical: h.bottom_condition = sn::ConicalHoleBottom{tidy(f.tip_angle)}; break;
    default: h.bottom_condition = sn::FlatHoleBottom{}; break;
  }
  return h;
}

// Passes along the face's length (its local x): the ISO frame's x across them, y along them.
sn::Feature planar_face(const pr::Feature& f, const std::string& id) {
  const LocalFrame lf = frame_of(f);
  sn::PlanarFace p;
  p.its_id = id;
  p.feature_placement = placement_at(lf, -f.length / 2, f.width / 2, 0, -1);
  p.depth = depth_plane(f.depth);
  p.course_of_travel.distance = toleranced(f.length);
  p.course_of_travel.its_direction = {0, 1, 0};
  p.removal_boundary.profile_length = tidy(f.width);
  return p;
}

sn::Feature closed_pocket(const pr::Feature& f, const std::string& id) {
  const LocalFrame lf = frame_of(f);
  sn::ClosedPocket p;
  p.its_id = id;
  p.feature_placement = placement_at(lf, 0, 0, 1, 0);
  p.depth = depth_plane(f.depth);
  if (f.through) p.bottom_condition = sn::ThroughPocketBottomCondition{};
  if (f.floor_radius > 1e-6) p.planar_radius = toleranced(f.floor_radius);
  switch (f.outline) {
    case pr::Outline::Rectangle:
      p.feature_boundary = sn::RectangularClosedProfile{std::nullopt, toleranced(f.width), toleranced(f.length)};
      if (f.corner_radius > 1e-6) p.orthogonal_radius = toleranced(f.corner_radius);
      break;
    case pr::Outline::Circle: p.feature_boundary = sn::CircularClosedProfile{std::nullopt, toleranced(f.diameter)}; break;
    default: {
      const auto outline = local_outline(f);
      p.feature_boundary = sn::GeneralClosedProfile{std::nullopt, run_curve(outline, 0, outline.size())};
    }
  }
  return p;
}

sn::Feature open_pocket(const pr::Feature& f, const std::string& id) {
  const LocalFrame lf = frame_of(f);
  sn::OpenPocket p;
  p.its_id = id;
  p.feature_placement = placement_at(lf, 0, 0, 1, 0);
  p.depth = depth_plane(f.depth);
  if (f.through) p.bottom_condition = sn::ThroughPocketBottomCondition{};
  if (f.floor_radius > 1e-6) p.planar_radius = toleranced(f.floor_radius);
  if (f.corner_radius > 1e-6) p.orthogonal_radius = toleranced(f.corner_radius);
  const auto outline = local_outline(f);
  const std::size_t n = outline.size();
  // The longest run of open edges, then the walls from its end round to its start.
  std::size_t best_start = 0, best_len = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!outline[i].open || outline[(i + n - 1) % n].open) continue;
    std::size_t len = 0;
    while (len < n && outline[(i + len) % n].open) ++len;
    if (len > best_len) best_len = len, best_start = i;
  }
  if (best_len == 0 || best_len == n) {
    p.open_boundary = sn::GeneralProfile{std::nullopt, run_curve(outline, 0, n)};
    return p;
  }
  p.open_boundary = sn::GeneralProfile{std::nullopt, run_curve(outline, best_start, best_len)};
  p.wall_boundary = sn::GeneralProfile{std::nullopt, run_curve(outline, best_start + best_len, n - best_len)};
  return p;
}

sn::Feature slot(const pr::Feature& f, const std::string& id) {
  const LocalFrame lf = frame_of(f);
  sn::Slot s;
  s.its_id = id;
  s.feature_placement = placement_at(lf, -f.length / 2, 0, 1, 0);
  s.depth = depth_plane(f.depth);
  s.course_of_travel.distance = toleranced(f.length);
  s.course_of_travel.its_direction = {1, 0, 0};
  s.swept_shape = sn::LinearProfile{std::nullopt, tidy(f.width)};
  for (auto e : f.slot_ends) {
    s.end_conditions.push_back(e == pr::SlotEnd::Radiused ? sn::SlotEndType::Radiused
                               : e == pr::SlotEnd::Flat   ? sn::SlotEndType::Flat
                                                          : sn::SlotEndType::Open);
  }
  return s;
}

// A step's local y points into the part (to its wall): the ISO frame sits at one end of the
// open edge, x along it.
sn::Feature step(const pr::Feature& f, const std::string& id) {
  const LocalFrame lf = frame_of(f);
  sn::Step s;
  s.its_id = id;
  s.feature_placement = placement_at(lf, -f.length / 2, -f.width / 2, 1, 0);
  s.depth = depth_plane(f.depth);
  s.open_boundary.distance = toleranced(f.length);
  s.open_boundary.its_direction = {1, 0, 0};
  return s;
}

sn::Feature outside_profile(const pr::Feature& f, const std::string& id) {
  const LocalFrame lf = frame_of(f);
  sn::GeneralOutsideProfile p;
  p.its_id = id;
  p.feature_placement = placement_at(lf, 0, 0, 1, 0);
  p.depth = depth_plane(f.depth);
  p.profile_swept_shape.distance = toleranced(f.depth);
  p.profile_swept_shape.its_direction = {0, 0, -1};
  const auto outline = local_outline(f);
  p.feature_boundary = run_curve(outline, 0, outline.size());
  p.closed = true;
  return p;
}

}  // namespace

std::vector<std::string> feature_ids(const std::vector<const pr::Feature*>& features) {
  std::map<pr::FeatureKind, int> counts;
  std::vector<std::string> ids;
  for (const auto* f : features) {
    const std::string n = std::to_string(++counts[f->kind]);
    switch (f->kind) {
      case pr::FeatureKind::PlanarFace: ids.push_back("PLANAR FACE" + n); break;
      case pr::FeatureKind::RoundHole: ids.push_back("HOLE" + n + " D=" + number_text(f->diameter) + "MM"); break;
      case pr::FeatureKind::ClosedPocket: ids.push_back("POCKET" + n); break;
      case pr::FeatureKind::OpenPocket: ids.push_back("OPEN POCKET" + n); break;
      case pr::FeatureKind::Slot: ids.push_back("SLOT" + n); break;
      case pr::FeatureKind::Step: ids.push_back("STEP" + n); break;
      case pr::FeatureKind::GeneralOutsideProfile: ids.push_back("PROFILE" + n); break;
    }
  }
  return ids;
}

sn::CompositeCurve outline_curve(const std::vector<pr::OutlineVertex>& outline) { return run_curve(outline, 0, outline.size()); }

sn::Feature to_stepnc(const pr::Feature& f, const std::string& id) {
  switch (f.kind) {
    case pr::FeatureKind::PlanarFace: return planar_face(f, id);
    case pr::FeatureKind::RoundHole: return round_hole(f, id);
    case pr::FeatureKind::ClosedPocket: return closed_pocket(f, id);
    case pr::FeatureKind::OpenPocket: return open_pocket(f, id);
    case pr::FeatureKind::Slot: return slot(f, id);
    case pr::FeatureKind::Step: return step(f, id);
    case pr::FeatureKind::GeneralOutsideProfile: return outside_profile(f, id);
  }
  return round_hole(f, id);
}

}  // namespace ncbridge::process_planner
