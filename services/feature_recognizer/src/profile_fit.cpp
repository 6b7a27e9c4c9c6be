#include "profile_fit.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <utility>
#include <vector>
#include <cmath>
#include <numbers>

namespace ncbridge::feature_recognizer {
namespace {

double cross(Point2 o, Point2 a, Point2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

Ring convex_hull(Ring pts) {
  std::sort(pts.begin(), pts.end(), [](Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (pts.size() < 3) return pts;
  Ring hull(2 * pts.size());
  std::size_t k = 0;
  for (const auto& p : pts) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

// Least-squares circle through points (Kåsa's algebraic fit); nullopt when they are collinear.
std::optional<std::pair<Point2, double>> fit_circle(const std::vector<Point2>& pts) {
  if (pts.size() < 3) return std::nullopt;
  double mx = 0, my = 0;
  for (const auto& p : pts) mx += p.x, my += p.y;
  mx /= static_cast<double>(pts.size()), my /= static_cast<double>(pts.size());
  double suu = 0, svv = 0, suv = 0, suuu = 0, svvv = 0, suvv = 0, svuu = 0;
  for (const auto& p : pts) {
    const double u = p.x - mx, v = p.y - my;
    suu += u * u, svv += v * v, suv += u * v;
    suuu += u * u * u, svvv += v * v * v, suvv += u * v * v, svuu += v * u * u;
  }
  const double det = suu * svv - suv * suv;
  if (std::abs(det) < 1e-12 * std::max(1.0, suu * svv)) return std::nullopt;
  const double bu = (suuu + suvv) / 2, bv = (svvv + svuu) / 2;
  const double uc = (bu * svv - bv * suv) / det, vc = (bv * suu - bu * suv) / det;
  const Point2 c{mx + uc, my + vc};
  double r = 0;
  for (const auto& p : pts) r += std::hypot(p.x - c.x, p.y - c.y);
  return std::pair{c, r / static_cast<double>(pts.size())};
}

// Every vertex of a swept area lies on or inside the exact one, within the chord tolerance (the
// tool disk and the arcs are inscribed polygons), so the farthest vertex from the fitted centre
// is the arc's radius, where the mean would be short of it by up to that tolerance.
double farthest(const std::vector<Point2>& pts, Point2 c) {
  double r = 0;
  for (const auto& p : pts) r = std::max(r, std::hypot(p.x - c.x, p.y - c.y));
  return r;
}

// The corner radius of a rounded rectangle from the outline's vertices at its four corners:
// in the rectangle's frame, those beyond the tangent points of a corner of radius `estimate`
// (with a margin), a circle fitted to each corner's; the mean of the four. Nullopt when a
// corner has too few vertices to fit or the fits disagree (not a rounded rectangle's corners).
std::optional<double> corner_radius_from_vertices(const Ring& outline, const OrientedRectangle& rect, double estimate) {
  const double a = rect.angle_deg * std::numbers::pi / 180, ux = std::cos(a), uy = std::sin(a);
  const double hl = rect.length / 2, hw = rect.width / 2, zone = 1.1 * estimate + 0.05;
  std::array<std::vector<Point2>, 4> corners;
  for (const auto& p : outline) {
    const double dx = p.x - rect.center.x, dy = p.y - rect.center.y;
    const double u = dx * ux + dy * uy, v = -dx * uy + dy * ux;
    if (std::abs(u) < hl - zone || std::abs(v) < hw - zone) continue;
    corners[(u > 0 ? 1 : 0) + (v > 0 ? 2 : 0)].push_back({u, v});
  }
  double sum = 0, lo = 1e300, hi = 0;
  for (const auto& pts : corners) {
    const auto circle = fit_circle(pts);
    if (!circle) return std::nullopt;
    const double r = farthest(pts, circle->first);
    sum += r, lo = std::min(lo, r), hi = std::max(hi, r);
  }
  if (hi - lo > 0.05 * hi + 0.02) return std::nullopt;
  return sum / 4;
}

// How far the outline stands in from each corner of the rectangle: the distance from the
// corner to the nearest outline edge, mean of the four. A rounded corner of radius r stands
// (√2 − 1) r in and lacks (4 − π)/4 r² of the rectangle; a 45° chamfer of leg c stands c/√2 in
// and lacks c²/2. For one inset the two missing areas differ by a quarter, so the area the
// outline lacks tells a chamfer from a radius.
double mean_corner_inset(const Ring& outline, const OrientedRectangle& rect) {
  const double a = rect.angle_deg * std::numbers::pi / 180, ux = std::cos(a), uy = std::sin(a);
  const double hl = rect.length / 2, hw = rect.width / 2;
  double total = 0;
  for (const double su : {-1.0, 1.0}) {
    for (const double sv : {-1.0, 1.0}) {
      const Point2 corner{rect.center.x + su * hl * ux - sv * hw * uy, rect.center.y + su * hl * uy + sv * hw * ux};
      double nearest = 1e300;
      for (std::size_t i = 0; i < outline.size(); ++i) {
        const Point2 p = outline[i], q = outline[(i + 1) % outline.size()];
        const double dx = q.x - p.x, dy = q.y - p.y, len2 = dx * dx + dy * dy;
        const double t = len2 > 0 ? std::clamp(((corner.x - p.x) * dx + (corner.y - p.y) * dy) / len2, 0.0, 1.0) : 0.0;
        nearest = std::min(nearest, std::hypot(p.x + t * dx - corner.x, p.y + t * dy - corner.y));
      }
      total += nearest;
    }
  }
  return total / 4;
}

}  // namespace

double perimeter(const Ring& ring) {
  double total = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto& a = ring[i];
    const auto& b = ring[(i + 1) % ring.size()];
    total += std::hypot(b.x - a.x, b.y - a.y);
  }
  return total;
}

OrientedRectangle minimum_area_rectangle(const Ring& points) {
  const Ring hull = convex_hull(points);
  OrientedRectangle best;
  double best_area = -1;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const auto& a = hull[i];
    const auto& b = hull[(i + 1) % hull.size()];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    if (len < 1e-9) continue;
    const double ux = (b.x - a.x) / len, uy = (b.y - a.y) / len;
    double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
    for (const auto& p : hull) {
      const double u = p.x * ux + p.y * uy, v = -p.x * uy + p.y * ux;
      umin = std::min(umin, u), umax = std::max(umax, u);
      vmin = std::min(vmin, v), vmax = std::max(vmax, v);
    }
    const double area = (umax - umin) * (vmax - vmin);
    // Prefer axis-aligned boxes among (nearly) equal areas, so rounding noise does not rotate them.
    if (best_area < 0 || area < best_area * (1 - 1e-9)) {
      best_area = area;
      const double uc = (umin + umax) / 2, vc = (vmin + vmax) / 2;
      best.center = {uc * ux - vc * uy, uc * uy + vc * ux};
      double angle = std::atan2(uy, ux) * 180 / std::numbers::pi;
      double length = umax - umin, width = vmax - vmin;
      if (width > length) std::swap(length, width), angle += 90;
      angle = std::fmod(angle + 360, 180);
      if (angle > 180 - 1e-6) angle = 0;
      best.length = length;
      best.width = width;
      best.angle_deg = angle;
    }
  }
  if (hull.size() < 3 && !hull.empty()) best.center = hull.front();
  return best;
}

Profile fit_closed_profile(const Ring& outline, double area) {
  Profile profile;
  profile.outline = outline;
  const auto rect = minimum_area_rectangle(outline);
  profile.length = rect.length;
  profile.width = rect.width;
  profile.angle_deg = rect.angle_deg;
  if (rect.length <= 0 || rect.width <= 0) {
    profile.shape = ProfileShape::GeneralClosed;
    return profile;
  }
  const double circle_area = std::numbers::pi * rect.length * rect.width / 4;
  if (rect.width > 0.98 * rect.length && std::abs(area - circle_area) < 0.02 * circle_area) {
    profile.shape = ProfileShape::Circular;
    const auto circle = fit_circle(outline);
    profile.diameter = circle ? 2 * farthest(outline, circle->first) : (rect.length + rect.width) / 2;
    profile.angle_deg = 0;
    return profile;
  }
  // A rounded rectangle lacks (4 - pi) r^2 of its enclosing rectangle.
  const double missing = std::max(0.0, rect.length * rect.width - area);
  // Chamfered corners (45°): the inset along the diagonals accounts for the missing area as
  // chamfers (2 c², c = √2 × inset) and not as radii (5.0 × inset²). The outline is kept exact
  // as a general closed profile; the tool's radius rounding a pocket's chamfer ends adds little.
  const double inset = mean_corner_inset(outline, rect);
  if (inset > 0.1) {
    const double as_chamfer = 4 * inset * inset, as_radius = (4 - std::numbers::pi) * std::pow(inset / (std::sqrt(2.0) - 1), 2);
    const double leg = std::sqrt(2.0) * inset;
    const double expected_perimeter = 2 * (rect.length + rect.width) - (8 - 4 * std::sqrt(2.0)) * leg;
    if (std::abs(missing - as_chamfer) < std::abs(missing - as_radius) && std::abs(missing - as_chamfer) < 0.1 * as_chamfer &&
        std::abs(perimeter(outline) - expected_perimeter) < 0.02 * expected_perimeter) {
      profile.shape = ProfileShape::GeneralClosed;
      profile.corner_chamfer = leg;
      return profile;
    }
  }
  const double r = std::sqrt(missing / (4 - std::numbers::pi));
  if (r <= rect.width / 2 + 1e-6) {
    // The radius matches the area by construction; the perimeter confirms the shape.
    const double expected_perimeter = 2 * (rect.length + rect.width) - (8 - 2 * std::numbers::pi) * r;
    if (std::abs(perimeter(outline) - expected_perimeter) < 0.02 * expected_perimeter) {
      profile.shape = ProfileShape::Rectangular;
      const auto fitted = r >= 0.5 ? corner_radius_from_vertices(outline, rect, r) : std::nullopt;
      const double radius = fitted ? *fitted : r;
      profile.corner_radius = radius < 0.05 ? 0 : radius;
      return profile;
    }
  }
  profile.shape = ProfileShape::GeneralClosed;
  return profile;
}

}  // namespace ncbridge::feature_recognizer
