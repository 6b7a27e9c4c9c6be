// Arc fitting: can one arc (or helix) replace the moves from vertex `first` to `last`?
// Candidate circles all pass through the first vertex (and the last, unless the run closes on
// itself); each candidate is checked against the band as fit.hpp describes.
#include <cmath>
#include <vector>

#include "ncbridge/toolpath_optimizer/fit.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

struct Planar {
  double u, v, n;  // plane axes relative to the first vertex; normal axis absolute
};

// Centre of the circle through the origin, b and c (relative coordinates).
bool circumcentre(Planar b, Planar c, double& cu, double& cv) {
  const double d = 2 * (b.u * c.v - b.v * c.u);
  const double b2 = b.u * b.u + b.v * b.v, c2 = c.u * c.u + c.v * c.v;
  if (std::abs(d) <= 1e-12 * (b2 + c2)) return false;
  cu = (c.v * b2 - b.v * c2) / d;
  cv = (b.u * c2 - c.u * b2) / d;
  return true;
}

class ArcCheck {
 public:
  ArcCheck(std::span<const FitVertex> v, std::size_t first, std::size_t last, const FitOptions& o)
      : v_(v), first_(first), last_(last), o_(o) {
    origin_ = to_plane(v[first].p, o.plane);
    points_.resize(last - first + 1);
    for (std::size_t i = first; i <= last; ++i) {
      const PlanePoint p = to_plane(v[i].p, o.plane);
      points_[i - first] = {p.first - origin_.first, p.second - origin_.second, p.normal};
    }
  }
  const std::vector<Planar>& points() const { return points_; }
  bool closed() const {
    const Planar& e = points_.back();
    return std::hypot(e.u, e.v) <= 1e-12;
  }

  // Checks the circle with centre (cu, cv) relative to the first vertex, after rounding it.
  bool check(double cu, double cv, ArcGeometry& out) const {
    if (o_.centre_resolution > 0) {
      const double q = o_.centre_resolution;
      cu = std::round((origin_.first + cu) / q) * q - origin_.first;
      cv = std::round((origin_.second + cv) / q) * q - origin_.second;
    }
    const double r = std::hypot(cu, cv);
    if (!(r > 0) || r > o_.max_radius || r < o_.min_arc_radius) return false;
    const double tol = o_.tolerance - o_.margin;
    const std::size_t n = points_.size();
    // Signed turning of each step about the centre.
    steps_.resize(n);
    double sum = 0;
    double pu = -cu, pv = -cv;
    for (std::size_t i = 1; i < n; ++i) {
      const double qu = points_[i].u - cu, qv = points_[i].v - cv;
      steps_[i] = std::atan2(pu * qv - pv * qu, pu * qu + pv * qv);
      sum += steps_[i];
      pu = qu, pv = qv;
    }
    const double dir = sum >= 0 ? 1.0 : -1.0;
    const double total = sum * dir;
    if (total <= 1e-9 || total > 2 * kPi + 1e-9) return false;
    const double n0 = points_.front().n, n1 = points_.back().n;
    if (!o_.helical && std::abs(n1 - n0) > 1e-12) return false;
    const double a0 = std::atan2(-cv, -cu);
    double raw = 0, tau_prev = 0, e_prev = 0;
    for (std::size_t i = 1; i < n; ++i) {
      const double step = steps_[i] * dir;
      if (step < -0.5) return false;  // runs backwards round the centre
      raw += step;
      const double tau = std::min(std::max(tau_prev, raw), total);
      const double hn = n0 + (n1 - n0) * (tau / total);
      const Planar& p = points_[i];
      double e2;
      if (tau == raw) {
        const double rho = std::hypot(p.u - cu, p.v - cv);
        e2 = (rho - r) * (rho - r) + (p.n - hn) * (p.n - hn);
      } else {
        const double a = a0 + dir * tau;
        const double hu = cu + r * std::cos(a) - p.u, hv = cv + r * std::sin(a) - p.v;
        e2 = hu * hu + hv * hv + (p.n - hn) * (p.n - hn);
      }
      const double e = std::sqrt(e2);
      const double half = (tau - tau_prev) / 2;
      const double c1 = 1 - std::cos(half), c2 = half - std::sin(half);
      const double chord = r * std::sqrt(c1 * c1 + c2 * c2);
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
  std::span<const FitVertex> v_;
  std::size_t first_, last_;
  const FitOptions& o_;
  PlanePoint origin_;
  std::vector<Planar> points_;
  mutable std::vector<double> steps_;
};

}  // namespace

bool arc_fits(std::span<const FitVertex> v, std::size_t first, std::size_t last, const FitOptions& options,
              ArcGeometry& geometry) {
  if (last < first + 2) return false;
  const ArcCheck check(v, first, last, options);
  const auto& p = check.points();
  const std::size_t n = p.size();
  double cu = 0, cv = 0;
  if (!check.closed()) {
    // The circle through the first, middle and last vertex.
    if (circumcentre(p[n / 2], p[n - 1], cu, cv) && check.check(cu, cv, geometry)) return true;
    // Least squares with the centre on the chord's bisector (through both ends):
    // |p - c|^2 - r^2 is linear in the position t along the bisector.
    const double mu = p[n - 1].u / 2, mv = p[n - 1].v / 2;
    const double h2 = mu * mu + mv * mv;
    const double len = std::sqrt(h2) * 2;
    const double nu = -p[n - 1].v / len, nv = p[n - 1].u / len;
    double ab = 0, bb = 0;
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const double du = p[i].u - mu, dv = p[i].v - mv;
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
    const double pu = p[i].u, pv = p[i].v, k = (pu * pu + pv * pv) / 2;
    suu += pu * pu, suv += pu * pv, svv += pv * pv;
    ru += pu * k, rv += pv * k;
  }
  const double det = suu * svv - suv * suv;
  if (std::abs(det) <= 1e-18) return false;
  return check.check((ru * svv - rv * suv) / det, (suu * rv - suv * ru) / det, geometry);
}

}  // namespace ncbridge::toolpath_optimizer
