// Arc fitting: can one arc (or helix) replace the moves from vertex `first` to `last`?
// Candidate circles all pass through the first vertex (and the last, unless the run closes on
// itself); each candidate is checked against the band as fit.hpp describes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "ncbridge/toolpath_optimizer/fit.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

// Centre of the circle through the origin, b and c (relative coordinates).
bool circumcentre(const PlanePoint& b, const PlanePoint& c, double& cu, double& cv) {
  const double d = 2 * (b.first * c.second - b.second * c.first);
  const double b2 = b.first * b.first + b.second * b.second, c2 = c.first * c.first + c.second * c.second;
  if (std::abs(d) <= 1e-12 * (b2 + c2)) return false;
  cu = (c.second * b2 - b.second * c2) / d;
  cv = (b.first * c2 - c.first * b2) / d;
  return true;
}

// atan2(y, x) to within a few 1e-16 rad without libm: folded into the first octant, then
// atan(t) = k/8 + atan(u) with tan(k/8) the nearest tabulated value and |u| <= tan(1/16), whose
// series converges fast. Every step of every candidate takes one of these.
inline double step_angle(double y, double x) {
  static constexpr double kTan[7] = {0.0,
                                     0.12565513657513097,   // tan(1/8)
                                     0.25534192122103627,   // tan(2/8)
                                     0.39362657592563277,   // tan(3/8)
                                     0.54630248984379050,   // tan(4/8)
                                     0.72148444099090450,   // tan(5/8)
                                     0.93159645994407250};  // tan(6/8)
  const double ax = std::abs(x), ay = std::abs(y);
  const bool swap = ay > ax;
  const double num = swap ? ax : ay, den = swap ? ay : ax;
  if (!(den > 0)) return std::atan2(y, x);  // (0, 0), NaN
  const double t = num / den;                // in [0, 1]
  // The tabulated tangent nearest t (t * 8 is close to the angle in eighths, then by the table).
  int j = std::min(6, static_cast<int>(t * 8 + 0.5));
  while (j < 6 && t > (kTan[j] + kTan[j + 1]) / 2) ++j;
  while (j > 0 && t < (kTan[j - 1] + kTan[j]) / 2) --j;
  const double c = kTan[j];
  const double u = (t - c) / (1 + t * c), u2 = u * u;
  double a = j / 8.0 + u * (1 - u2 * (1.0 / 3 - u2 * (1.0 / 5 - u2 * (1.0 / 7 - u2 * (1.0 / 9 - u2 * (1.0 / 11 - u2 / 13))))));
  if (swap) a = kPi / 2 - a;
  if (x < 0) a = kPi - a;
  return std::signbit(y) ? -a : a;
}

// How far an arc of radius 1 between two points strays from the chord between them, compared at
// equal fractions: sqrt((1 - cos h)^2 + (h - sin h)^2), h = half the angle (fit.hpp). Small
// angles by the two series (more exact there than the differences, and without libm).
inline double unit_chord_bound(double half) {
  double c1, c2;
  if (std::abs(half) < 0.25) {
    const double h2 = half * half;
    c1 = h2 / 2 * (1 - h2 / 12 * (1 - h2 / 30 * (1 - h2 / 56 * (1 - h2 / 90 * (1 - h2 / 132)))));
    c2 = half * h2 / 6 * (1 - h2 / 20 * (1 - h2 / 42 * (1 - h2 / 72 * (1 - h2 / 110 * (1 - h2 / 156)))));
  } else {
    c1 = 1 - std::cos(half);
    c2 = half - std::sin(half);
  }
  return std::sqrt(c1 * c1 + c2 * c2);
}

// x rounded to the nearest integer (ties away from zero, as std::round), without a libm call
// for the values centres take.
inline double round_to_integer(double x) {
  constexpr double kLarge = 4503599627370496.0;  // 2^52: from here on every double is an integer
  if (!(std::abs(x) < kLarge)) return x;
  const double t = static_cast<double>(static_cast<std::int64_t>(x));  // towards zero
  const double rest = x - t;
  if (rest >= 0.5) return t + 1;
  if (rest <= -0.5) return t - 1;
  return t;
}

// The farthest any point of a plane arc piece is from an input segment, at most: the arc runs
// from a to b (points on the circle of centre c and radius r, turning `dir`, less than a quarter
// turn) at height `normal`; the segment from P to Q. Along the segment's line and across it,
// the distance of an arc point is A + r cos(angle - phi): its extremes lie at the piece's ends
// or where the arc's radius points along (or across) the line. The bound combines the largest
// distance across the line, how far the piece overshoots the segment's ends along it, and the
// segment's largest height off the arc's plane. Negative where the segment is a point.
struct Point2 {
  double u, v;
};

inline double piece_bound(Point2 a, Point2 b, Point2 c, double r, double dir, const PlanePoint& P, const PlanePoint& Q,
                          double normal) {
  const double du = Q.first - P.first, dv = Q.second - P.second;
  const double length = std::sqrt(du * du + dv * dv);
  if (!(length > 1e-12)) return -1;
  const double tu = du / length, tv = dv / length;  // along the segment
  const double nu = -tv, nv = tu;                    // across it
  auto across = [&](Point2 x) { return nu * (x.u - P.first) + nv * (x.v - P.second); };
  auto along = [&](Point2 x) { return tu * (x.u - P.first) + tv * (x.v - P.second); };
  double cross_max = std::max(std::abs(across(a)), std::abs(across(b)));
  double along_min = std::min(along(a), along(b)), along_max = std::max(along(a), along(b));
  const double au = a.u - c.u, av = a.v - c.v, bu = b.u - c.u, bv = b.v - c.v;
  // Whether the direction (x, y) from the centre lies on the piece.
  auto on_piece = [&](double x, double y) {
    return dir * (au * y - av * x) >= 0 && dir * (x * bv - y * bu) >= 0 && x * (au + bu) + y * (av + bv) > 0;
  };
  const double centre_across = across(c), centre_along = along(c);
  if (on_piece(nu, nv)) cross_max = std::max(cross_max, std::abs(centre_across + r));
  if (on_piece(-nu, -nv)) cross_max = std::max(cross_max, std::abs(centre_across - r));
  if (on_piece(tu, tv)) along_max = std::max(along_max, centre_along + r);
  if (on_piece(-tu, -tv)) along_min = std::min(along_min, centre_along - r);
  const double over = std::max({0.0, -along_min, along_max - length});
  const double height = std::max(std::abs(P.normal - normal), std::abs(Q.normal - normal));
  return std::sqrt(cross_max * cross_max + over * over + height * height);
}

// The candidate circles of one span: `p` are its vertices relative to the first (normal axis
// absolute), p.size() >= 3.
class ArcCheck {
 public:
  ArcCheck(std::span<const PlanePoint> p, PlanePoint origin, const FitOptions& o, FitWorkspace& w)
      : p_(p), origin_(origin), o_(o), w_(w) {}
  bool closed() const {
    const PlanePoint& e = p_.back();
    return e.first * e.first + e.second * e.second <= 1e-24;
  }

  // Checks the circle with centre (cu, cv) relative to the first vertex, after rounding it.
  bool check(double cu, double cv, ArcGeometry& out) const {
    if (o_.centre_resolution > 0) {
      const double q = o_.centre_resolution;
      cu = round_to_integer((origin_.first + cu) / q) * q - origin_.first;
      cv = round_to_integer((origin_.second + cv) / q) * q - origin_.second;
    }
    const double r = std::sqrt(cu * cu + cv * cv);
    if (!(r > 0) || r > o_.max_radius || r < o_.min_arc_radius) return false;
    const double tol = o_.tolerance - o_.margin;
    const std::size_t n = p_.size();
    // Every vertex within the band of the circle first (a point's distance to any point of the
    // circle is at least |rho - r|): most candidate circles fail here, before any angle.
    std::vector<double>& rho = w_.rho;
    rho.resize(n);
    for (std::size_t i = 1; i < n; ++i) {
      const double qu = p_[i].first - cu, qv = p_[i].second - cv;
      rho[i] = std::sqrt(qu * qu + qv * qv);
      if (std::abs(rho[i] - r) > tol) return false;
    }
    // Signed turning of each step about the centre.
    std::vector<double>& steps = w_.steps;
    steps.resize(n);
    double sum = 0;
    double pu = -cu, pv = -cv;
    for (std::size_t i = 1; i < n; ++i) {
      const double qu = p_[i].first - cu, qv = p_[i].second - cv;
      steps[i] = step_angle(pu * qv - pv * qu, pu * qu + pv * qv);
      sum += steps[i];
      pu = qu, pv = qv;
    }
    const double dir = sum >= 0 ? 1.0 : -1.0;
    const double total = sum * dir;
    if (total <= 1e-9 || total > 2 * kPi + 1e-9) return false;
    const double n0 = p_.front().normal, n1 = p_.back().normal;
    if (!o_.helical && std::abs(n1 - n0) > 1e-12) return false;
    double a0 = 0;
    bool have_a0 = false;  // the start angle, taken only when a vertex is held back
    double raw = 0, tau_prev = 0, e_prev = 0;
    const bool helix = n1 != n0;
    // The arc ends at the last vertex, which is only within the band of the circle: a control
    // (and the checker) moves a spiral whose radius goes linearly from r to the last vertex's.
    const double spiral = rho[n - 1] - r;
    double mu_prev = 0, mv_prev = 0;  // the circle's point paired with the previous vertex
    double delta_prev = 0;            // the spiral's radius there, less r
    for (std::size_t i = 1; i < n; ++i) {
      const double step = steps[i] * dir;
      if (step < -0.5) return false;  // runs backwards round the centre
      raw += step;
      const double tau = std::min(std::max(tau_prev, raw), total);
      const double hn = n0 + (n1 - n0) * (tau / total);
      const double delta = spiral * (tau / total);
      const PlanePoint& q = p_[i];
      double e2, mu, mv;
      if (tau == raw && rho[i] > 1e-12) {
        const double rho_i = rho[i];
        e2 = (rho_i - r - delta) * (rho_i - r - delta) + (q.normal - hn) * (q.normal - hn);
        mu = cu + (q.first - cu) * (r / rho_i);
        mv = cv + (q.second - cv) * (r / rho_i);
      } else {
        if (!have_a0) {
          a0 = step_angle(-cv, -cu);
          have_a0 = true;
        }
        const double a = a0 + dir * tau;
        const double ca = std::cos(a), sa = std::sin(a);
        mu = cu + r * ca;
        mv = cv + r * sa;
        const double hu = mu + delta * ca - q.first, hv = mv + delta * sa - q.second;
        e2 = hu * hu + hv * hv + (q.normal - hn) * (q.normal - hn);
      }
      const double e = std::sqrt(e2);
      if (e > tol) return false;
      // The spiral between the two paired points against the input segment between the
      // vertices: a plane arc exactly (piece_bound on the circle, plus how far the spiral is off
      // it there), else compared at equal fractions (fit.hpp).
      double piece = -1;
      if (!helix && tau - tau_prev < kPi / 2) {
        piece = piece_bound({mu_prev, mv_prev}, {mu, mv}, {cu, cv}, r, dir, p_[i - 1], q, n0);
        if (piece >= 0) piece += std::max(std::abs(delta_prev), std::abs(delta));
      }
      if (piece < 0) {
        piece = (r + std::max(std::abs(delta), std::abs(delta_prev))) * unit_chord_bound((tau - tau_prev) / 2) +
                std::abs(delta - delta_prev) + std::max(e, e_prev);
      }
      if (piece > tol) return false;
      tau_prev = tau;
      e_prev = e;
      mu_prev = mu;
      mv_prev = mv;
      delta_prev = delta;
    }
    out.plane = o_.plane;
    out.first_centre = origin_.first + cu;
    out.second_centre = origin_.second + cv;
    out.ccw = dir > 0;
    out.extra_turns = 0;
    return true;
  }

 private:
  std::span<const PlanePoint> p_;
  PlanePoint origin_;
  const FitOptions& o_;
  FitWorkspace& w_;
};

}  // namespace

bool arc_fits(std::span<const FitVertex> v, std::size_t first, std::size_t last, const FitOptions& options,
              ArcGeometry& geometry, FitWorkspace& w) {
  if (last < first + 2) return false;
  const PlanePoint origin = to_plane(v[first].p, options.plane);
  if (!w.valid || w.start != first) {
    w.points.clear();
    w.start = first;
    w.valid = true;
  }
  for (std::size_t i = first + w.points.size(); i <= last; ++i) {
    const PlanePoint q = to_plane(v[i].p, options.plane);
    w.points.push_back({q.first - origin.first, q.second - origin.second, q.normal});
  }
  const std::span<const PlanePoint> p(w.points.data(), last - first + 1);
  const ArcCheck check(p, origin, options, w);
  const std::size_t n = p.size();
  double cu = 0, cv = 0;
  if (!check.closed()) {
    // The circle through the first, middle and last vertex.
    if (circumcentre(p[n / 2], p[n - 1], cu, cv) && check.check(cu, cv, geometry)) return true;
    // Three vertices: the least squares circle below is that same circle.
    if (n == 3) return false;
    // Least squares with the centre on the chord's bisector (through both ends):
    // |p - c|^2 - r^2 is linear in the position t along the bisector.
    const double mu = p[n - 1].first / 2, mv = p[n - 1].second / 2;
    const double h2 = mu * mu + mv * mv;
    const double len = std::sqrt(h2) * 2;
    const double nu = -p[n - 1].second / len, nv = p[n - 1].first / len;
    double ab = 0, bb = 0;
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const double du = p[i].first - mu, dv = p[i].second - mv;
      const double a = du * du + dv * dv - h2, b = du * nu + dv * nv;
      ab += a * b;
      bb += b * b;
    }
    if (bb <= 0) return false;
    const double t = ab / (2 * bb);
    return check.check(mu + t * nu, mv + t * nv, geometry);
  }
  // A closed run: a full circle through the first vertex.
  if (n < 4) return false;
  if (circumcentre(p[n / 3], p[2 * n / 3], cu, cv) && check.check(cu, cv, geometry)) return true;
  // Least squares through the first vertex: |p|^2 - 2 c.p = 0 is linear in c.
  double suu = 0, suv = 0, svv = 0, ru = 0, rv = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double pu = p[i].first, pv = p[i].second, k = (pu * pu + pv * pv) / 2;
    suu += pu * pu, suv += pu * pv, svv += pv * pv;
    ru += pu * k, rv += pv * k;
  }
  const double det = suu * svv - suv * suv;
  if (std::abs(det) <= 1e-18) return false;
  return check.check((ru * svv - rv * suv) / det, (suu * rv - suv * ru) / det, geometry);
}

bool arc_fits(std::span<const FitVertex> v, std::size_t first, std::size_t last, const FitOptions& options,
              ArcGeometry& geometry) {
  FitWorkspace w;
  return arc_fits(v, first, last, options, geometry, w);
}

}  // namespace ncbridge::toolpath_optimizer
