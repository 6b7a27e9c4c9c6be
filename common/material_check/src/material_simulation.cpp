#include "ncbridge/material_check/material_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace ncbridge::material_check {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kHelixChord = 0.0005;  // mm: helical arcs as chords
constexpr double kNone = std::numeric_limits<double>::infinity();

// One piece of a move: a straight 3D segment, or an arc in a horizontal plane.
struct Piece {
  bool arc = false;
  Point3 a, b;              // straight: ends; arc: start and end (same z)
  Point2 centre;
  double radius = 0, start = 0, sweep = 0;
};

double wrap(double a) {  // into [0, 2 pi)
  a = std::fmod(a, 2 * kPi);
  return a < 0 ? a + 2 * kPi : a;
}

template <class Out>
void pieces_of(const Point3& from, const Motion& m, Out&& out) {
  if (!m.arc_centre || std::abs(m.arc_sweep) < 1e-12) {
    out(Piece{false, from, m.end, {}, 0, 0, 0});
    return;
  }
  const Point2 c = *m.arc_centre;
  const double radius = std::hypot(from.x - c.x, from.y - c.y);
  const double start = std::atan2(from.y - c.y, from.x - c.x);
  if (radius < 1e-9) {
    out(Piece{false, from, m.end, {}, 0, 0, 0});
    return;
  }
  if (std::abs(m.end.z - from.z) < 1e-12) {
    Piece p;
    p.arc = true;
    p.a = from;
    p.b = m.end;
    p.centre = c;
    p.radius = radius;
    p.start = start;
    p.sweep = m.arc_sweep;
    out(p);
    return;
  }
  // A helix: chords whose ends lie on it.
  const double step = kHelixChord < radius ? 2 * std::acos(1 - kHelixChord / radius) : kPi / 2;
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(m.arc_sweep) / step)));
  Point3 prev = from;
  for (int k = 1; k <= n; ++k) {
    const double f = static_cast<double>(k) / n;
    const double a = start + m.arc_sweep * f;
    const Point3 q = k == n ? m.end
                            : Point3{c.x + radius * std::cos(a), c.y + radius * std::sin(a), from.z + (m.end.z - from.z) * f};
    out(Piece{false, prev, q, {}, 0, 0, 0});
    prev = q;
  }
}

// The lowest cutter surface over a straight piece at p (+inf when out of reach), and the
// distance from the axis where it is reached.
double lowest_on_segment(double px, double py, const Piece& s, const CutterShape& cutter, double& r_at) {
  const double R = cutter.radius;
  const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y, dz = s.b.z - s.a.z;
  const double qx = px - s.a.x, qy = py - s.a.y;
  const double L2 = dx * dx + dy * dy;
  if (L2 < 1e-24) {
    const double r = std::hypot(qx, qy);
    if (r > R) return kNone;
    r_at = r;
    return std::min(s.a.z, s.b.z) + cutter.height_at(r);
  }
  const double w = qx * dx + qy * dy;
  if (std::abs(dz) < 1e-12) {
    const double t = std::clamp(w / L2, 0.0, 1.0);
    const double r = std::hypot(qx - t * dx, qy - t * dy);
    if (r > R) return kNone;
    r_at = r;
    return s.a.z + cutter.height_at(r);
  }
  const double q2 = qx * qx + qy * qy;
  const double disc = w * w - L2 * (q2 - R * R);
  if (disc < 0) return kNone;
  const double root = std::sqrt(disc);
  const double t0 = std::max(0.0, (w - root) / L2), t1 = std::min(1.0, (w + root) / L2);
  if (t0 > t1) return kNone;
  auto dist = [&](double t) { return std::hypot(qx - t * dx, qy - t * dy); };
  if (cutter.kind == CutterShape::Kind::Flat) {
    const double t = dz < 0 ? t1 : t0;
    r_at = std::min(R, dist(t));
    return s.a.z + t * dz;
  }
  // z(t) + height(r(t)) is convex on [t0, t1]: golden-section search.
  auto f = [&](double t) { return s.a.z + t * dz + cutter.height_at(std::min(R, dist(t))); };
  constexpr double g = 0.6180339887498949;
  double lo = t0, hi = t1;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int k = 0; k < 40 && hi - lo > 1e-9; ++k) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  double best_t = (lo + hi) / 2, best = f(best_t);
  for (double t : {t0, t1}) {
    if (const double v = f(t); v < best) best = v, best_t = t;
  }
  r_at = std::min(R, dist(best_t));
  return best;
}

double lowest_on_arc(double px, double py, const Piece& s, const CutterShape& cutter, double& r_at) {
  const double R = cutter.radius;
  const double qx = px - s.centre.x, qy = py - s.centre.y;
  const double rho = std::hypot(qx, qy);
  double d;
  bool inside = std::abs(s.sweep) >= 2 * kPi - 1e-12;
  if (!inside && rho > 1e-12) {
    const double phi = std::atan2(qy, qx);
    const double along = s.sweep > 0 ? wrap(phi - s.start) : wrap(s.start - phi);
    inside = along <= std::abs(s.sweep);
  }
  if (inside) {
    d = std::abs(rho - s.radius);
  } else {
    d = std::min(std::hypot(px - s.a.x, py - s.a.y), std::hypot(px - s.b.x, py - s.b.y));
  }
  if (d > R) return kNone;
  r_at = d;
  return s.a.z + cutter.height_at(d);
}

// The XY range of cell centres a straight piece reaches on the row at y.
bool row_interval(double y, const Piece& s, double R, double& lo, double& hi) {
  lo = kNone, hi = -kNone;
  auto disk = [&](const Point3& c) {
    const double dy = y - c.y;
    if (std::abs(dy) > R) return;
    const double w = std::sqrt(R * R - dy * dy);
    lo = std::min(lo, c.x - w), hi = std::max(hi, c.x + w);
  };
  disk(s.a);
  disk(s.b);
  const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  const double L = std::hypot(dx, dy);
  if (L > 1e-12) {
    const double ux = dx / L, uy = dy / L;
    const double yy = y - s.a.y;
    // 0 <= (x - ax) ux + yy uy <= L  and  -R <= (x - ax) uy - yy ux <= R
    double a = -kNone, b = kNone;
    auto clamp_linear = [&](double coef, double constant, double low, double high) {
      // low <= coef * X + constant <= high, X = x - ax
      if (std::abs(coef) < 1e-15) {
        if (constant < low || constant > high) a = kNone, b = -kNone;
        return;
      }
      double x1 = (low - constant) / coef, x2 = (high - constant) / coef;
      if (x1 > x2) std::swap(x1, x2);
      a = std::max(a, x1), b = std::min(b, x2);
    };
    clamp_linear(ux, yy * uy, 0, L);
    clamp_linear(uy, -yy * ux, -R, R);
    if (a <= b) lo = std::min(lo, s.a.x + a), hi = std::max(hi, s.a.x + b);
  }
  return lo <= hi;
}

struct Box {
  double xmin, ymin, xmax, ymax;
};

Box arc_box(const Piece& s, double R) {
  Box b{std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y), std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y)};
  const bool full = std::abs(s.sweep) >= 2 * kPi - 1e-12;
  for (int k = 0; k < 4; ++k) {
    const double phi = k * kPi / 2;
    const double along = s.sweep > 0 ? wrap(phi - s.start) : wrap(s.start - phi);
    if (full || along <= std::abs(s.sweep)) {
      const double x = s.centre.x + s.radius * std::cos(phi), y = s.centre.y + s.radius * std::sin(phi);
      b.xmin = std::min(b.xmin, x), b.xmax = std::max(b.xmax, x), b.ymin = std::min(b.ymin, y), b.ymax = std::max(b.ymax, y);
    }
  }
  return {b.xmin - R, b.ymin - R, b.xmax + R, b.ymax + R};
}

}  // namespace

double automatic_cell(const setup::Stock& stock) {
  const double area = std::max(1e-6, stock.size(0) * stock.size(1));
  return std::max(0.1, std::sqrt(area / 4e6));
}

HeightGrid::HeightGrid(const setup::Stock& stock, double cell) : cell_(cell) {
  if (!(cell > 0)) throw std::invalid_argument("material check: the sample spacing must be positive");
  // Cell centres start a fraction of a cell inside the stock so that they do not fall on the
  // round coordinates walls usually have.
  const double inset = 0.1372 * cell;
  x0_ = stock.min[0] + inset - cell / 2;
  y0_ = stock.min[1] + inset - cell / 2;
  nx_ = std::max(1, static_cast<int>(std::floor((stock.max[0] - stock.min[0] - inset) / cell)) + 1);
  ny_ = std::max(1, static_cast<int>(std::floor((stock.max[1] - stock.min[1] - inset) / cell)) + 1);
  const double count = static_cast<double>(nx_) * ny_;
  if (count > 2e8) throw std::invalid_argument("material check: too many samples; give a larger sample spacing");
  heights_.assign(static_cast<std::size_t>(count), static_cast<float>(stock.max[2]));
}

int HeightGrid::first_column(double x_lo) const { return std::max(0, static_cast<int>(std::ceil((x_lo - x0_) / cell_ - 0.5))); }
int HeightGrid::last_column(double x_hi) const { return std::min(nx_ - 1, static_cast<int>(std::floor((x_hi - x0_) / cell_ - 0.5))); }
int HeightGrid::first_row(double y_lo) const { return std::max(0, static_cast<int>(std::ceil((y_lo - y0_) / cell_ - 0.5))); }
int HeightGrid::last_row(double y_hi) const { return std::min(ny_ - 1, static_cast<int>(std::floor((y_hi - y0_) / cell_ - 0.5))); }

MaterialSimulation::MaterialSimulation(const setup::Stock& stock, double cell, std::vector<Point2> probes)
    : stock_(stock), grid_(stock, cell), probes_(std::move(probes)) {
  probe_heights_.resize(probes_.size());
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    const auto& p = probes_[k];
    const bool in = p.x >= stock.min[0] && p.x <= stock.max[0] && p.y >= stock.min[1] && p.y <= stock.max[1];
    probe_heights_[k] = static_cast<float>(in ? stock.max[2] : stock.min[2]);
  }
  bucket_ = std::max(1.0, 16 * cell);
  bx_ = std::max(1, static_cast<int>(std::ceil(stock.size(0) / bucket_)) + 2);
  by_ = std::max(1, static_cast<int>(std::ceil(stock.size(1) / bucket_)) + 2);
  buckets_.resize(static_cast<std::size_t>(bx_) * by_);
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    const int i = std::clamp(static_cast<int>(std::floor((probes_[k].x - stock.min[0]) / bucket_)) + 1, 0, bx_ - 1);
    const int j = std::clamp(static_cast<int>(std::floor((probes_[k].y - stock.min[1]) / bucket_)) + 1, 0, by_ - 1);
    buckets_[static_cast<std::size_t>(j) * bx_ + i].push_back(k);
  }
}

// Calls visit(height, lowest cutter surface, distance from the axis) for every sample the move
// reaches (grid cells first, then probes); `height` refers to the sample's stored height.
template <class Visit>
void MaterialSimulation::sweep(const Point3& from, const Motion& motion, const CutterShape& cutter, Visit&& visit) const {
  const double R = cutter.radius;
  auto& grid = const_cast<HeightGrid&>(grid_);
  auto& probe_heights = const_cast<std::vector<float>&>(probe_heights_);
  auto probes_in = [&](const Box& box, auto&& at) {
    if (probes_.empty()) return;
    const int i0 = std::clamp(static_cast<int>(std::floor((box.xmin - stock_.min[0]) / bucket_)) + 1, 0, bx_ - 1);
    const int i1 = std::clamp(static_cast<int>(std::floor((box.xmax - stock_.min[0]) / bucket_)) + 1, 0, bx_ - 1);
    const int j0 = std::clamp(static_cast<int>(std::floor((box.ymin - stock_.min[1]) / bucket_)) + 1, 0, by_ - 1);
    const int j1 = std::clamp(static_cast<int>(std::floor((box.ymax - stock_.min[1]) / bucket_)) + 1, 0, by_ - 1);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        for (auto k : buckets_[static_cast<std::size_t>(j) * bx_ + i]) at(k);
      }
    }
  };
  pieces_of(from, motion, [&](const Piece& s) {
    if (!s.arc) {
      const Box box{std::min(s.a.x, s.b.x) - R, std::min(s.a.y, s.b.y) - R, std::max(s.a.x, s.b.x) + R,
                    std::max(s.a.y, s.b.y) + R};
      const int j0 = grid.first_row(box.ymin), j1 = grid.last_row(box.ymax);
      for (int j = j0; j <= j1; ++j) {
        const double y = grid.y(j);
        double lo, hi;
        if (!row_interval(y, s, R, lo, hi)) continue;
        const int i0 = grid.first_column(lo), i1 = grid.last_column(hi);
        for (int i = i0; i <= i1; ++i) {
          double r = 0;
          const double h = lowest_on_segment(grid.x(i), y, s, cutter, r);
          if (h != kNone) visit(grid.height(i, j), h, r);
        }
      }
      probes_in(box, [&](std::size_t k) {
        double r = 0;
        const double h = lowest_on_segment(probes_[k].x, probes_[k].y, s, cutter, r);
        if (h != kNone) visit(probe_heights[k], h, r);
      });
    } else {
      const Box box = arc_box(s, R);
      const int j0 = grid.first_row(box.ymin), j1 = grid.last_row(box.ymax);
      const int i0 = grid.first_column(box.xmin), i1 = grid.last_column(box.xmax);
      const double outer = s.radius + R, inner = std::max(0.0, s.radius - R);
      for (int j = j0; j <= j1; ++j) {
        const double y = grid.y(j);
        const double dy = y - s.centre.y;
        if (std::abs(dy) > outer) continue;
        // Only the annulus about the centre can be reached: skip the columns of its hole.
        const double wo = std::sqrt(outer * outer - dy * dy);
        const int a0 = std::max(i0, grid.first_column(s.centre.x - wo)), a1 = std::min(i1, grid.last_column(s.centre.x + wo));
        const double wi = std::abs(dy) < inner ? std::sqrt(inner * inner - dy * dy) : -1;
        for (int i = a0; i <= a1; ++i) {
          const double x = grid.x(i);
          if (wi > 0 && std::abs(x - s.centre.x) < wi - 1e-9) continue;
          double r = 0;
          const double h = lowest_on_arc(x, y, s, cutter, r);
          if (h != kNone) visit(grid.height(i, j), h, r);
        }
      }
      probes_in(box, [&](std::size_t k) {
        double r = 0;
        const double h = lowest_on_arc(probes_[k].x, probes_[k].y, s, cutter, r);
        if (h != kNone) visit(probe_heights[k], h, r);
      });
    }
  });
}

CutResult MaterialSimulation::feed(const Point3& from, const Motion& motion, const CutterShape& cutter) {
  CutResult out;
  const double bottom = stock_.min[2];
  const double cell_area = grid_.cell() * grid_.cell();
  const float* grid_begin = grid_.heights().data();
  const float* grid_end = grid_begin + grid_.size();
  sweep(from, motion, cutter, [&](float& height, double h, double r) {
    const double lowered = std::max(h, bottom);
    if (lowered < height) {
      const double drop = height - lowered;
      if (r <= 0.5 * cutter.radius) out.centre_depth = std::max(out.centre_depth, drop);
      if (&height >= grid_begin && &height < grid_end) out.removed_volume += drop * cell_area;
      height = static_cast<float>(lowered);
      out.removed = true;
    }
  });
  return out;
}

double MaterialSimulation::penetration(const Point3& from, const Motion& motion, const CutterShape& cutter) const {
  double deepest = 0;
  const double bottom = stock_.min[2];
  sweep(from, motion, cutter, [&](float& height, double h, double) {
    deepest = std::max(deepest, static_cast<double>(height) - std::max(h, bottom));
  });
  return deepest;
}

}  // namespace ncbridge::material_check
