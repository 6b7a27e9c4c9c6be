#include "to_stepnc_strategy.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace ncbridge::feature_recognizer {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLevelTolerance = 1e-3;  // mm: points of one cutting level
constexpr double kShortestPass = 1.0;     // mm: shorter straight moves are not passes
constexpr double kSplineChordTolerance = 0.001;  // mm: B-splines are followed as chords this close

struct Segment {
  stepnc::CartesianPoint a, b;
  double length() const { return std::hypot(b.x - a.x, b.y - a.y); }
};

}  // namespace

std::vector<stepnc::CartesianPoint> curve_points(const stepnc::CompositeCurve& curve) {
  std::vector<stepnc::CartesianPoint> out;
  for (const auto& segment : curve.segments) {
    if (const auto* line = std::get_if<stepnc::Polyline>(&segment)) {
      out.insert(out.end(), line->points.begin(), line->points.end());
      continue;
    }
    if (const auto* spline = std::get_if<stepnc::BSplineCurve>(&segment)) {
      const auto points = stepnc::bspline_polyline(*spline, kSplineChordTolerance);
      out.insert(out.end(), points.begin(), points.end());
      continue;
    }
    const auto& arc = std::get<stepnc::TrimmedCircle>(segment);
    const auto& p = arc.position;
    const stepnc::Direction& r = p.ref_direction;
    const stepnc::Direction y{p.axis.y * r.z - p.axis.z * r.y, p.axis.z * r.x - p.axis.x * r.z,
                              p.axis.x * r.y - p.axis.y * r.x};
    const double sweep = stepnc::sweep_degrees(arc);
    const int steps = std::max(1, static_cast<int>(std::ceil(sweep / 10)));
    out.push_back(arc.trim_1_point);
    for (int k = 1; k < steps; ++k) {
      const double t = (arc.trim_1_parameter + (arc.sense_agreement ? 1 : -1) * sweep * k / steps) * kPi / 180;
      const double f = static_cast<double>(k) / steps;
      out.push_back({p.location.x + arc.radius * (std::cos(t) * r.x + std::sin(t) * y.x),
                     p.location.y + arc.radius * (std::cos(t) * r.y + std::sin(t) * y.y),
                     arc.trim_1_point.z + f * (arc.trim_2_point.z - arc.trim_1_point.z)});
    }
    out.push_back(arc.trim_2_point);
  }
  return out;
}

PathDirections analyse_path_directions(const std::vector<const stepnc::CompositeCurve*>& cutting_curves, bool passes) {
  PathDirections out;
  // Horizontal moves, in order, and the deepest level among them.
  std::vector<Segment> moves;
  double deepest = 1e300;
  for (const auto* curve : cutting_curves) {
    const auto points = curve_points(*curve);
    for (std::size_t i = 1; i < points.size(); ++i) {
      const Segment s{points[i - 1], points[i]};
      if (std::abs(s.a.z - s.b.z) > kLevelTolerance || s.length() < 1e-9) continue;
      moves.push_back(s);
      deepest = std::min(deepest, s.a.z);
    }
  }
  if (moves.empty()) return out;
  std::vector<Segment> level;
  for (const auto& s : moves) {
    if (std::abs(s.a.z - deepest) <= kLevelTolerance) level.push_back(s);
  }
  if (passes) {
    // Closed loops ending the level (a finishing contour): left out.
    for (bool found = true; found && level.size() > 1;) {
      found = false;
      const auto& end = level.back().b;
      double length = 0;
      for (std::size_t j = level.size(); j-- > 0;) {
        length += level[j].length();
        if (length > kShortestPass && std::hypot(level[j].a.x - end.x, level[j].a.y - end.y) < 1e-2) {
          if (j == 0) break;
          level.resize(j);
          found = true;
          break;
        }
      }
    }
  }

  // Rotation: the sign of the area the level's path sweeps about +Z (shoelace over its moves,
  // about its first point: the path closed back to it, so that a link between two loops adds
  // nothing however far the part lies from the origin).
  double twice_area = 0;
  const auto& o = level.front().a;
  for (const auto& s : level) twice_area += (s.a.x - o.x) * (s.b.y - o.y) - (s.b.x - o.x) * (s.a.y - o.y);
  if (std::abs(twice_area) > 1e-6) out.rotation = twice_area > 0 ? stepnc::RotDirection::Ccw : stepnc::RotDirection::Cw;

  // Feed direction: the direction (modulo 180 degrees, 1-degree bins) with the longest total
  // length of straight passes; its first pass gives the sense.
  std::map<int, double> length_per_bin;
  auto bin_of = [](const Segment& s) {
    double a = std::atan2(s.b.y - s.a.y, s.b.x - s.a.x) * 180 / kPi;
    if (a < 0) a += 180;
    if (a >= 179.5) a -= 180;
    return static_cast<int>(std::lround(a));
  };
  for (const auto& s : level) {
    if (s.length() >= kShortestPass) length_per_bin[bin_of(s)] += s.length();
  }
  if (length_per_bin.empty()) return out;
  const int best = std::max_element(length_per_bin.begin(), length_per_bin.end(),
                                    [](const auto& x, const auto& y) { return x.second < y.second; })->first;
  const Segment* first = nullptr;
  for (const auto& s : level) {
    if (s.length() < kShortestPass || bin_of(s) != best) continue;
    if (!first) {
      first = &s;
      continue;
    }
    // The next pass along the same direction that lies beside the first: the stepover side.
    const double len = first->length();
    const double fx = (first->b.x - first->a.x) / len, fy = (first->b.y - first->a.y) / len;
    const double offset = fx * (s.a.y - first->a.y) - fy * (s.a.x - first->a.x);
    if (std::abs(offset) > 1e-3) {
      out.stepover_direction = offset > 0 ? stepnc::LeftOrRight::Left : stepnc::LeftOrRight::Right;
      break;
    }
  }
  const double len = first->length();
  out.feed_direction = stepnc::Direction{(first->b.x - first->a.x) / len, (first->b.y - first->a.y) / len, 0};
  return out;
}

}  // namespace ncbridge::feature_recognizer
