#include "feature_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncbridge::process_planner {

namespace pr = part_reader;

LocalFrame frame_of(const pr::Feature& f) {
  const auto& p = f.placement;
  const double n = std::hypot(p.ref_direction.x, p.ref_direction.y);
  LocalFrame frame{p.location.x, p.location.y, p.location.z, 1, 0};
  if (n > 1e-12) frame.cx = p.ref_direction.x / n, frame.sx = p.ref_direction.y / n;
  return frame;
}

std::vector<pr::OutlineVertex> local_outline(const pr::Feature& f) {
  switch (f.outline) {
    case pr::Outline::Rectangle: {
      const double hl = f.length / 2, hw = f.width / 2;
      const double r = std::clamp(f.corner_radius, 0.0, std::min(hl, hw));
      const double b = std::tan(std::numbers::pi / 8);  // a quarter turn
      if (r <= 1e-9) return {{-hl, -hw}, {hl, -hw}, {hl, hw}, {-hl, hw}};
      std::vector<pr::OutlineVertex> v;
      v.push_back({-hl + r, -hw, 0});
      v.push_back({hl - r, -hw, b});
      v.push_back({hl, -hw + r, 0});
      v.push_back({hl, hw - r, b});
      v.push_back({hl - r, hw, 0});
      v.push_back({-hl + r, hw, b});
      v.push_back({-hl, hw - r, 0});
      v.push_back({-hl, -hw + r, b});
      // Drop zero-length straight edges (a slot-like rectangle whose ends are whole half circles).
      std::vector<pr::OutlineVertex> out;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const auto& a = v[i];
        const auto& next = v[(i + 1) % v.size()];
        if (a.bulge == 0 && std::hypot(next.x - a.x, next.y - a.y) < 1e-9) continue;
        out.push_back(a);
      }
      return out;
    }
    case pr::Outline::Circle: {
      const double r = f.diameter / 2;
      return {{r, 0, 1}, {-r, 0, 1}};
    }
    case pr::Outline::General: return f.boundary;
    case pr::Outline::None: break;
  }
  return {};
}

double tightest_corner(const std::vector<pr::OutlineVertex>& outline, bool inside) {
  double tightest = 1e9;
  const std::size_t n = outline.size();
  if (n < 2) return tightest;
  auto edge_dir = [&](std::size_t i, bool at_end) {
    // The tangent of edge i at its start or end.
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % n];
    double dx = b.x - a.x, dy = b.y - a.y;
    const double len = std::hypot(dx, dy);
    if (len < 1e-12) return XY{0, 0};
    dx /= len, dy /= len;
    if (a.bulge == 0) return XY{dx, dy};
    const double half = 2 * std::atan(a.bulge);  // the tangent turns by half the sweep at each end
    const double t = at_end ? half : -half;
    return XY{dx * std::cos(t) - dy * std::sin(t), dx * std::sin(t) + dy * std::cos(t)};
  };
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % n];
    if (a.bulge != 0) {
      const double chord = std::hypot(b.x - a.x, b.y - a.y);
      const double sweep = 4 * std::atan(std::abs(a.bulge));
      const double radius = chord / (2 * std::sin(sweep / 2));
      // A counter-clockwise arc turns the way a counter-clockwise outline does: seen from inside
      // it is a corner to fit; a clockwise one is a corner for a cutter outside.
      if ((a.bulge > 0) == inside) tightest = std::min(tightest, radius);
    }
    // The corner at the end of edge i.
    const XY in = edge_dir(i, true), out = edge_dir((i + 1) % n, false);
    const double turn = in.x * out.y - in.y * out.x;
    const double along = in.x * out.x + in.y * out.y;
    if (std::abs(turn) < 1e-6 && along > 0) continue;  // tangent: no corner
    if ((turn > 0) == inside) tightest = 0;
  }
  return tightest;
}

std::vector<XY> outline_points(const std::vector<pr::OutlineVertex>& outline, double step) {
  std::vector<XY> points;
  const std::size_t n = outline.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % n];
    points.push_back({a.x, a.y});
    if (a.bulge == 0) continue;
    const double sweep = 4 * std::atan(a.bulge);  // signed
    const double chord = std::hypot(b.x - a.x, b.y - a.y);
    if (chord < 1e-12) continue;
    const double d = chord * (1 - a.bulge * a.bulge) / (4 * a.bulge);
    const double mx = (a.x + b.x) / 2, my = (a.y + b.y) / 2;
    const double cx = mx - (b.y - a.y) / chord * d, cy = my + (b.x - a.x) / chord * d;
    const double r = std::hypot(a.x - cx, a.y - cy);
    const double start = std::atan2(a.y - cy, a.x - cx);
    const int k = std::max(2, static_cast<int>(std::ceil(std::abs(sweep) * 180 / std::numbers::pi / step)));
    for (int j = 1; j < k; ++j) {
      const double t = start + sweep * j / k;
      points.push_back({cx + r * std::cos(t), cy + r * std::sin(t)});
    }
  }
  return points;
}

double narrowest(const pr::Feature& f) {
  switch (f.outline) {
    case pr::Outline::Rectangle: return std::min(f.length, f.width);
    case pr::Outline::Circle: return f.diameter;
    default: break;
  }
  const auto points = outline_points(local_outline(f));
  if (points.empty()) return 0;
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const auto& v : points) {
    xmin = std::min(xmin, v.x), xmax = std::max(xmax, v.x), ymin = std::min(ymin, v.y), ymax = std::max(ymax, v.y);
  }
  return std::min(xmax - xmin, ymax - ymin);
}

}  // namespace ncbridge::process_planner
