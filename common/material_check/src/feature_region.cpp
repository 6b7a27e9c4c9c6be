#include "ncbridge/material_check/feature_region.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

#include "ncbridge/common/error.hpp"

namespace ncbridge::material_check {

namespace {

namespace sn = stepnc;
constexpr double kPi = std::numbers::pi;
constexpr double kJoin = 0.01;  // mm: profile pieces closer than this join

[[noreturn]] void fail(const std::string& source, const std::string& id, const std::string& what) {
  throw InputError({source, 0, 0}, "feature '" + id + "': " + what);
}

double size_of(const sn::TolerancedLengthMeasure& m) { return m.theoretical_size; }

// A placement given inside `frame` (a profile's or a path's own placement), as a frame.
PlanarFrame compose(const PlanarFrame& frame, const std::optional<sn::Axis2Placement3d>& inner) {
  if (!inner) return frame;
  PlanarFrame out;
  out.origin = frame.to_program(inner->location.x, inner->location.y);
  out.angle = frame.angle + std::atan2(inner->ref_direction.y, inner->ref_direction.x);
  out.z = frame.z + inner->location.z;
  return out;
}

double distance(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

PlanarCurve counter_clockwise(PlanarCurve c) {
  if (c.signed_area() < 0) c = c.reversed();
  return c;
}

PlanarCurve line_curve(Point2 a, Point2 b) {
  PlanarCurve c;
  c.segments.emplace_back(LineSegment{a, b});
  return c;
}

PlanarCurve polygon_curve(const std::vector<Point2>& corners) {
  PlanarCurve c;
  c.closed = true;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    c.segments.emplace_back(LineSegment{corners[i], corners[(i + 1) % corners.size()]});
  }
  return c;
}

PlanarCurve closed_profile_curve(const sn::ClosedProfile& profile, const PlanarFrame& frame, const std::string& id,
                                 const std::string& source) {
  return std::visit(
      [&](const auto& p) -> PlanarCurve {
        using P = std::decay_t<decltype(p)>;
        const PlanarFrame f = compose(frame, p.placement);
        if constexpr (std::is_same_v<P, sn::RectangularClosedProfile>) {
          const double w = size_of(p.profile_width), l = size_of(p.profile_length);
          if (!(w > 0 && l > 0)) fail(source, id, "RECTANGULAR_CLOSED_PROFILE needs a positive width and length");
          return rounded_rectangle(f.origin, l, w, 0, f.angle);
        } else if constexpr (std::is_same_v<P, sn::CircularClosedProfile>) {
          const double d = size_of(p.diameter);
          if (!(d > 0)) fail(source, id, "CIRCULAR_CLOSED_PROFILE needs a positive diameter");
          return circle(f.origin, d / 2);
        } else {
          PlanarCurve c = planar_curve_of(p.closed_profile_shape, f);
          if (c.segments.empty()) fail(source, id, "GENERAL_CLOSED_PROFILE has no curve");
          if (distance(start_of(c.segments.front()), end_of(c.segments.back())) > kJoin) {
            fail(source, id, "GENERAL_CLOSED_PROFILE does not close");
          }
          c.closed = true;
          return counter_clockwise(c);
        }
      },
      profile);
}

PlanarCurve open_profile_curve(const sn::OpenProfile& profile, const PlanarFrame& frame) {
  return std::visit(
      [&](const auto& p) -> PlanarCurve {
        using P = std::decay_t<decltype(p)>;
        const PlanarFrame f = compose(frame, p.placement);
        if constexpr (std::is_same_v<P, sn::LinearProfile>) {
          return line_curve(f.to_program(0, 0), f.to_program(p.profile_length, 0));
        } else {
          return planar_curve_of(p.its_profile, f);
        }
      },
      profile);
}

double depth_of(const sn::MachiningFeature& f, const std::string& source) {
  const double depth = -f.depth.position.location.z;
  if (!(depth > 0)) fail(source, f.its_id, "its depth plane is not below its placement (no depth)");
  return depth;
}

void set_depth(FeatureRegion& r, double depth, const setup::Stock& stock) {
  r.depth = depth;
  r.top_z = r.frame.z;
  r.floor_z = r.top_z - depth;
  if (r.floor_z <= stock.min[2] + 1e-6) r.through = true;
}

// How far the stock reaches from `origin` along the unit vector `dir`.
double stock_reach(const setup::Stock& stock, Point2 origin, Point2 dir) {
  double reach = -1e300;
  for (double x : {stock.min[0], stock.max[0]}) {
    for (double y : {stock.min[1], stock.max[1]}) reach = std::max(reach, (x - origin.x) * dir.x + (y - origin.y) * dir.y);
  }
  return reach;
}

// A band along the centre line a -> b of half-width `half`, each end radiused or square.
PlanarCurve slot_outline(Point2 a, Point2 b, double half, bool round_a, bool round_b) {
  const double len = distance(a, b);
  const double ux = (b.x - a.x) / len, uy = (b.y - a.y) / len;
  const double nx = -uy, ny = ux;  // left of travel
  const double angle = std::atan2(uy, ux);
  PlanarCurve c;
  c.closed = true;
  const Point2 a_right{a.x - nx * half, a.y - ny * half}, b_right{b.x - nx * half, b.y - ny * half};
  const Point2 b_left{b.x + nx * half, b.y + ny * half}, a_left{a.x + nx * half, a.y + ny * half};
  c.segments.emplace_back(LineSegment{a_right, b_right});
  if (round_b) c.segments.emplace_back(ArcSegment{b, half, angle - kPi / 2, kPi});
  else c.segments.emplace_back(LineSegment{b_right, b_left});
  c.segments.emplace_back(LineSegment{b_left, a_left});
  if (round_a) c.segments.emplace_back(ArcSegment{a, half, angle + kPi / 2, kPi});
  else c.segments.emplace_back(LineSegment{a_left, a_right});
  return c;
}

}  // namespace

Point2 PlanarFrame::to_program(double u, double v) const {
  const double c = std::cos(angle), s = std::sin(angle);
  return {origin.x + u * c - v * s, origin.y + u * s + v * c};
}

Point2 PlanarFrame::to_local(Point2 p) const {
  const double c = std::cos(angle), s = std::sin(angle);
  const double dx = p.x - origin.x, dy = p.y - origin.y;
  return {dx * c + dy * s, -dx * s + dy * c};
}

PlanarFrame frame_of(const sn::Axis2Placement3d& placement, const std::string& feature_id, const std::string& source_name) {
  const auto& a = placement.axis;
  const double n = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
  if (!(n > 0) || std::abs(a.x / n) > 1e-6 || std::abs(a.y / n) > 1e-6 || a.z <= 0) {
    fail(source_name, feature_id, "its placement axis is not +Z (only features machined from above are supported)");
  }
  PlanarFrame f;
  f.origin = {placement.location.x, placement.location.y};
  f.z = placement.location.z;
  const auto& r = placement.ref_direction;
  f.angle = std::hypot(r.x, r.y) > 1e-12 ? std::atan2(r.y, r.x) : 0;
  return f;
}

PlanarCurve planar_curve_of(const sn::CompositeCurve& curve, const PlanarFrame& frame) {
  PlanarCurve out;
  for (const auto& segment : curve.segments) {
    if (const auto* line = std::get_if<sn::Polyline>(&segment)) {
      for (std::size_t i = 1; i < line->points.size(); ++i) {
        const Point2 a = frame.to_program(line->points[i - 1].x, line->points[i - 1].y);
        const Point2 b = frame.to_program(line->points[i].x, line->points[i].y);
        if (distance(a, b) > 1e-9) out.segments.emplace_back(LineSegment{a, b});
      }
      continue;
    }
    const auto& arc = std::get<sn::TrimmedCircle>(segment);
    const Point2 centre = frame.to_program(arc.position.location.x, arc.position.location.y);
    const Point2 start = frame.to_program(arc.trim_1_point.x, arc.trim_1_point.y);
    const bool ccw = arc.sense_agreement == (arc.position.axis.z >= 0);
    const double sweep = sn::sweep_degrees(arc) * kPi / 180;
    out.segments.emplace_back(
        ArcSegment{centre, arc.radius, std::atan2(start.y - centre.y, start.x - centre.x), ccw ? sweep : -sweep});
  }
  if (!out.segments.empty() && distance(start_of(out.segments.front()), end_of(out.segments.back())) <= kJoin) {
    out.closed = true;
  }
  return out;
}

FeatureRegion feature_region(const sn::Feature& feature, std::size_t index, const setup::Stock& stock,
                             const std::string& source) {
  FeatureRegion r;
  r.feature_index = index;
  r.id = sn::feature_id(feature);
  std::visit(
      [&](const auto& f) {
        using F = std::decay_t<decltype(f)>;
        if constexpr (std::is_same_v<F, sn::ToolpathFeature>) {
          fail(source, r.id, "a TOOLPATH_FEATURE has no geometry to machine (its toolpath is given)");
        } else if constexpr (std::is_same_v<F, sn::Region>) {
          if (!f.feature_placement) fail(source, r.id, "REGION has no placement");
          r.frame = frame_of(*f.feature_placement, r.id, source);
          PlanarCurve c = planar_curve_of(f.proj_curve, r.frame);
          if (!c.closed || c.segments.empty()) fail(source, r.id, "its projected curve does not close");
          r.outline.push_back(counter_clockwise(c));
          if (!(f.depth.theoretical_size > 0)) fail(source, r.id, "REGION needs a positive depth");
          set_depth(r, f.depth.theoretical_size, stock);
        } else {
          r.frame = frame_of(f.feature_placement, r.id, source);
          const double depth = depth_of(f, source);
          if constexpr (std::is_same_v<F, sn::RoundHole>) {
            const double d = size_of(f.diameter);
            if (!(d > 0)) fail(source, r.id, "ROUND_HOLE needs a positive diameter");
            r.outline.push_back(circle(r.frame.origin, d / 2));
            r.hole_radius = d / 2;
            set_depth(r, depth, stock);
            if (std::holds_alternative<sn::ThroughBottomCondition>(f.bottom_condition)) {
              r.through = true;
            } else if (const auto* cone = std::get_if<sn::ConicalHoleBottom>(&f.bottom_condition)) {
              if (!r.through) r.cone_tip_angle = cone->tip_angle > 0 && cone->tip_angle < 180 ? cone->tip_angle : 118;
            }
          } else if constexpr (std::is_same_v<F, sn::PlanarFace>) {
            if (f.face_boundary) {
              r.outline.push_back(closed_profile_curve(*f.face_boundary, r.frame, r.id, source));
            } else {
              const PlanarFrame path = compose(r.frame, f.course_of_travel.placement);
              const auto& d = f.course_of_travel.its_direction;
              const double dn = std::hypot(d.x, d.y);
              const double length = size_of(f.course_of_travel.distance), width = f.removal_boundary.profile_length;
              if (!(dn > 0) || !(length > 0) || !(width > 0)) {
                fail(source, r.id, "PLANAR_FACE needs a course of travel and a removal boundary of positive length");
              }
              const Point2 u{d.x / dn, d.y / dn};
              // The removal boundary lies along local x; along local y when the course runs along x.
              const Point2 p = std::abs(u.y) < 1e-9 ? Point2{0, 1} : Point2{1, 0};
              auto at = [&](double s, double t) { return path.to_program(s * p.x + t * u.x, s * p.y + t * u.y); };
              r.outline.push_back(counter_clockwise(polygon_curve({at(0, 0), at(width, 0), at(width, length), at(0, length)})));
            }
            for (const auto& c : r.outline) r.open_edges.push_back(c);
            set_depth(r, depth, stock);
          } else if constexpr (std::is_same_v<F, sn::ClosedPocket>) {
            if (f.slope && std::abs(*f.slope) > 1e-9) fail(source, r.id, "pockets with sloped walls are not supported");
            PlanarCurve c = closed_profile_curve(f.feature_boundary, r.frame, r.id, source);
            if (const auto* rect = std::get_if<sn::RectangularClosedProfile>(&f.feature_boundary)) {
              const double corner = f.orthogonal_radius ? size_of(*f.orthogonal_radius) : 0;
              const double w = size_of(rect->profile_width), l = size_of(rect->profile_length);
              if (corner < 0 || 2 * corner > std::min(w, l) + 1e-9) {
                fail(source, r.id, "its orthogonal_radius does not fit the rectangle");
              }
              const PlanarFrame pf = compose(r.frame, rect->placement);
              c = rounded_rectangle(pf.origin, l, w, corner, pf.angle);
            }
            r.outline.push_back(c);
            set_depth(r, depth, stock);
            if (std::holds_alternative<sn::ThroughPocketBottomCondition>(f.bottom_condition)) r.through = true;
          } else if constexpr (std::is_same_v<F, sn::OpenPocket>) {
            if (f.slope && std::abs(*f.slope) > 1e-9) fail(source, r.id, "pockets with sloped walls are not supported");
            PlanarCurve open = open_profile_curve(f.open_boundary, r.frame);
            if (open.segments.empty()) fail(source, r.id, "OPEN_POCKET has an empty open_boundary");
            PlanarCurve c = open;
            if (f.wall_boundary) {
              PlanarCurve wall = open_profile_curve(*f.wall_boundary, r.frame);
              if (wall.segments.empty()) fail(source, r.id, "OPEN_POCKET has an empty wall_boundary");
              const Point2 oe = end_of(open.segments.back()), os = start_of(open.segments.front());
              if (distance(start_of(wall.segments.front()), oe) > kJoin) wall = wall.reversed();
              if (distance(start_of(wall.segments.front()), oe) > kJoin || distance(end_of(wall.segments.back()), os) > kJoin) {
                fail(source, r.id, "its open_boundary and wall_boundary do not join into one closed outline");
              }
              c.segments.insert(c.segments.end(), wall.segments.begin(), wall.segments.end());
            } else {
              const Point2 oe = end_of(open.segments.back()), os = start_of(open.segments.front());
              if (distance(oe, os) > kJoin) {
                c.segments.emplace_back(LineSegment{oe, os});
                r.open_edges.push_back(line_curve(oe, os));
              }
            }
            c.closed = true;
            if (std::abs(c.signed_area()) < 1e-9) fail(source, r.id, "its outline encloses no area");
            r.outline.push_back(counter_clockwise(c));
            set_depth(r, depth, stock);
            if (std::holds_alternative<sn::ThroughPocketBottomCondition>(f.bottom_condition)) r.through = true;
          } else if constexpr (std::is_same_v<F, sn::Slot>) {
            const auto* width_profile = std::get_if<sn::LinearProfile>(&f.swept_shape);
            if (!width_profile) fail(source, r.id, "only slots whose swept_shape is a LINEAR_PROFILE (their width) are supported");
            const double width = width_profile->profile_length;
            const double length = size_of(f.course_of_travel.distance);
            const auto& d = f.course_of_travel.its_direction;
            const double dn = std::hypot(d.x, d.y);
            if (!(width > 0) || !(length > 0) || !(dn > 0)) fail(source, r.id, "SLOT needs a positive width and course length");
            const PlanarFrame path = compose(r.frame, f.course_of_travel.placement);
            const Point2 a = path.to_program(0, 0), b = path.to_program(length * d.x / dn, length * d.y / dn);
            auto end_type = [&](std::size_t k) {
              return k < f.end_conditions.size() ? f.end_conditions[k] : sn::SlotEndType::Radiused;
            };
            for (std::size_t k = 0; k < f.end_conditions.size(); ++k) {
              if (f.end_conditions[k] == sn::SlotEndType::Loop) fail(source, r.id, "LOOP_SLOT_END_TYPE is not supported");
            }
            const bool round_a = end_type(0) == sn::SlotEndType::Radiused || end_type(0) == sn::SlotEndType::Woodruff;
            const bool round_b = end_type(1) == sn::SlotEndType::Radiused || end_type(1) == sn::SlotEndType::Woodruff;
            r.outline.push_back(slot_outline(a, b, width / 2, round_a, round_b));
            const double len = distance(a, b);
            const Point2 n{-(b.y - a.y) / len * width / 2, (b.x - a.x) / len * width / 2};
            if (end_type(0) == sn::SlotEndType::Open) r.open_edges.push_back(line_curve({a.x + n.x, a.y + n.y}, {a.x - n.x, a.y - n.y}));
            if (end_type(1) == sn::SlotEndType::Open) r.open_edges.push_back(line_curve({b.x - n.x, b.y - n.y}, {b.x + n.x, b.y + n.y}));
            set_depth(r, depth, stock);
          } else if constexpr (std::is_same_v<F, sn::Step>) {
            const auto& d = f.open_boundary.its_direction;
            const double dn = std::hypot(d.x, d.y);
            const double length = size_of(f.open_boundary.distance);
            if (!(length > 0) || !(dn > 0)) fail(source, r.id, "STEP needs an open boundary of positive length");
            const PlanarFrame path = compose(r.frame, f.open_boundary.placement);
            const Point2 a = path.to_program(0, 0), b = path.to_program(length * d.x / dn, length * d.y / dn);
            const Point2 u{(b.x - a.x) / length, (b.y - a.y) / length};
            const Point2 toward{-u.y, u.x};  // the step lies left of its wall: local +y
            const double reach = stock_reach(stock, a, toward);
            if (!(reach > 1e-6)) fail(source, r.id, "STEP lies outside the stock (nothing on its open side)");
            const Point2 c{b.x + toward.x * reach, b.y + toward.y * reach}, e{a.x + toward.x * reach, a.y + toward.y * reach};
            r.outline.push_back(polygon_curve({a, b, c, e}));
            r.open_edges.push_back(line_curve(c, e));
            set_depth(r, depth, stock);
          } else if constexpr (std::is_same_v<F, sn::GeneralOutsideProfile>) {
            if (!f.closed) fail(source, r.id, "GENERAL_OUTSIDE_PROFILE with an open boundary is not supported");
            PlanarCurve c = planar_curve_of(f.feature_boundary, r.frame);
            if (c.segments.empty()) fail(source, r.id, "GENERAL_OUTSIDE_PROFILE has no boundary curve");
            if (distance(start_of(c.segments.front()), end_of(c.segments.back())) > kJoin) {
              fail(source, r.id, "its feature_boundary does not close");
            }
            c.closed = true;
            const PlanarCurve outer = polygon_curve({{stock.min[0], stock.min[1]}, {stock.max[0], stock.min[1]},
                                                     {stock.max[0], stock.max[1]}, {stock.min[0], stock.max[1]}});
            r.outline.push_back(outer);
            PlanarCurve hole = counter_clockwise(c).reversed();
            r.outline.push_back(hole);
            r.open_edges.push_back(outer);
            set_depth(r, depth, stock);
          }
        }
      },
      feature);
  return r;
}

}  // namespace ncbridge::material_check
