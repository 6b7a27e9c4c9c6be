#include "ncbridge/stepnc/geometry.hpp"

#include <algorithm>
#include <cmath>

namespace ncbridge::stepnc {

double sweep_degrees(const TrimmedCircle& arc) {
  double sweep = arc.sense_agreement ? arc.trim_2_parameter - arc.trim_1_parameter
                                     : arc.trim_1_parameter - arc.trim_2_parameter;
  sweep = std::fmod(sweep, 360.0);
  if (sweep <= 0) sweep += 360.0;
  return sweep;
}

}  // namespace ncbridge::stepnc

namespace ncbridge::stepnc {

namespace {

struct Homogeneous {
  double x = 0, y = 0, z = 0, w = 1;
};

// The knot vector with every knot repeated by its multiplicity.
std::vector<double> expanded_knots(const BSplineCurve& c) {
  std::vector<double> u;
  for (std::size_t i = 0; i < c.knots.size(); ++i) u.insert(u.end(), static_cast<std::size_t>(c.knot_multiplicities[i]), c.knots[i]);
  return u;
}

CartesianPoint evaluate(const BSplineCurve& c, const std::vector<double>& u_knots, double u) {
  const auto p = static_cast<std::size_t>(c.degree);
  const std::size_t n = c.control_points.size() - 1;
  u = std::clamp(u, u_knots[p], u_knots[n + 1]);
  // The span k with u_knots[k] <= u < u_knots[k + 1], p <= k <= n (the last one at the end).
  std::size_t k = p;
  while (k < n && u >= u_knots[k + 1]) ++k;
  std::vector<Homogeneous> d(p + 1);
  for (std::size_t j = 0; j <= p; ++j) {
    const CartesianPoint& q = c.control_points[j + k - p];
    const double w = c.weights.empty() ? 1.0 : c.weights[j + k - p];
    d[j] = {q.x * w, q.y * w, q.z * w, w};
  }
  for (std::size_t r = 1; r <= p; ++r) {
    for (std::size_t j = p; j >= r; --j) {
      const double left = u_knots[j + k - p], right = u_knots[j + 1 + k - r];
      const double alpha = right > left ? (u - left) / (right - left) : 0.0;
      d[j] = {(1 - alpha) * d[j - 1].x + alpha * d[j].x, (1 - alpha) * d[j - 1].y + alpha * d[j].y,
              (1 - alpha) * d[j - 1].z + alpha * d[j].z, (1 - alpha) * d[j - 1].w + alpha * d[j].w};
    }
  }
  return {d[p].x / d[p].w, d[p].y / d[p].w, d[p].z / d[p].w};
}

double distance_to_chord(const CartesianPoint& p, const CartesianPoint& a, const CartesianPoint& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
  const double px = p.x - a.x, py = p.y - a.y, pz = p.z - a.z;
  const double length2 = dx * dx + dy * dy + dz * dz;
  const double t = length2 > 0 ? std::clamp((px * dx + py * dy + pz * dz) / length2, 0.0, 1.0) : 0.0;
  const double ex = px - t * dx, ey = py - t * dy, ez = pz - t * dz;
  return std::sqrt(ex * ex + ey * ey + ez * ez);
}

}  // namespace

std::string bspline_problem(const BSplineCurve& c) {
  if (c.degree < 1) return "degree below 1";
  if (c.control_points.size() < 2) return "fewer than two control points";
  const auto n = static_cast<long long>(c.control_points.size()) - 1;
  if (n < c.degree) return "fewer control points than degree + 1";
  if (c.knots.size() < 2 || c.knots.size() != c.knot_multiplicities.size()) {
    return "knots and knot multiplicities must be two or more lists of the same length";
  }
  long long sum = 0;
  for (std::size_t i = 0; i < c.knots.size(); ++i) {
    const int m = c.knot_multiplicities[i];
    const bool end = i == 0 || i + 1 == c.knots.size();
    if (m < 1 || m > c.degree + (end ? 1 : 0)) return "knot multiplicity " + std::to_string(m) + " out of range";
    if (i > 0 && !(c.knots[i] > c.knots[i - 1])) return "knots not ascending";
    if (!std::isfinite(c.knots[i])) return "knot not finite";
    sum += m;
  }
  if (sum != n + c.degree + 2) return "knot multiplicities do not add up to control points + degree + 1";
  if (!c.weights.empty()) {
    if (c.weights.size() != c.control_points.size()) return "not one weight per control point";
    for (double w : c.weights) {
      if (!(w > 0) || !std::isfinite(w)) return "weight not positive";
    }
  }
  return {};
}

CartesianPoint bspline_point(const BSplineCurve& curve, double u) { return evaluate(curve, expanded_knots(curve), u); }

std::vector<CartesianPoint> bspline_polyline(const BSplineCurve& curve, double tolerance) {
  const std::vector<double> u_knots = expanded_knots(curve);
  std::vector<CartesianPoint> out;
  constexpr int kSamplesPerSpan = 8;  // so that a span's turns are not missed between two chords
  constexpr int kMaxDepth = 24;
  // A bound on the points of one curve, whatever a file holds (huge coordinates would otherwise
  // halve every chord down to kMaxDepth): past it, chords are taken as they are.
  constexpr std::size_t kMaxPoints = 200000;
  struct Piece {
    double u0, u1;
    CartesianPoint p0, p1;
    int depth;
  };
  std::vector<Piece> stack;
  out.push_back(evaluate(curve, u_knots, curve.knots.front()));
  for (std::size_t span = 0; span + 1 < curve.knots.size(); ++span) {
    const double a = curve.knots[span], b = curve.knots[span + 1];
    for (int s = 0; s < kSamplesPerSpan; ++s) {
      const double u0 = a + (b - a) * s / kSamplesPerSpan;
      const double u1 = s + 1 == kSamplesPerSpan ? b : a + (b - a) * (s + 1) / kSamplesPerSpan;
      stack.push_back({u0, u1, out.back(), evaluate(curve, u_knots, u1), 0});
      while (!stack.empty()) {
        Piece piece = stack.back();
        stack.pop_back();
        const double um = (piece.u0 + piece.u1) / 2;
        const CartesianPoint mid = evaluate(curve, u_knots, um);
        if (piece.depth < kMaxDepth && out.size() + stack.size() < kMaxPoints &&
            distance_to_chord(mid, piece.p0, piece.p1) > tolerance) {
          stack.push_back({um, piece.u1, mid, piece.p1, piece.depth + 1});  // the second half after the first
          stack.push_back({piece.u0, um, piece.p0, mid, piece.depth + 1});
        } else {
          out.push_back(piece.p1);
        }
      }
    }
  }
  out.back() = evaluate(curve, u_knots, curve.knots.back());
  return out;
}

}  // namespace ncbridge::stepnc
