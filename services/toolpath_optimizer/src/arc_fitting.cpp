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
    for (std::size_t i = 1; i < n; ++i) {
      const double step = steps[i] * dir;
      if (step < -0.5) return false;  // runs backwards round the centre
      raw += step;
      const double tau = std::min(std::max(tau_prev, raw), total);
      const double hn = n0 + (n1 - n0) * (tau / total);
      const PlanePoint& q = p_[i];
      double e2;
      if (tau == raw) {
        const double rho_i = rho[i];
        e2 = (rho_i - r) * (rho_i - r) + (q.normal - hn) * (q.normal - hn);
      } else {
        if (!have_a0) {
          a0 = step_angle(-cv, -cu);
          have_a0 = true;
        }
        const double a = a0 + dir * tau;
        const double hu = cu + r * std::cos(a) - q.first, hv = cv + r * std::sin(a) - q.second;
        e2 = hu * hu + hv * hv + (q.normal - hn) * (q.normal - hn);
      }
      const double e = std::sqrt(e2);
      const double chord = r * unit_chord_bound((tau - tau_prev) / 2);
      if (e > tol || chord + std::max(e, e_prev) > tol) return false;
      tau_prev = tau;
      e_prev = e;
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
