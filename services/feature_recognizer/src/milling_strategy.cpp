#include "milling_strategy.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace ncbridge::feature_recognizer {
namespace {

constexpr double kLevel = 1e-3;

struct Straight {
  Point2 a, b;
  double length() const { return std::hypot(b.x - a.x, b.y - a.y); }
};

// The cutting moves at the layer's level (its entry ramps and plunges left out).
std::vector<std::vector<Point2>> level_runs(const Layer& layer) {
  std::vector<std::vector<Point2>> runs;
  for (const auto& path : layer.paths) {
    std::vector<Point2> run;
    for (std::size_t i = 1; i < path.size(); ++i) {
      const bool on_level = std::abs(path[i].z - layer.z) < kLevel && std::abs(path[i - 1].z - layer.z) < kLevel;
      if (on_level) {
        if (run.empty()) run.push_back({path[i - 1].x, path[i - 1].y});
        run.push_back({path[i].x, path[i].y});
      } else if (!run.empty()) {
        runs.push_back(std::move(run));
        run.clear();
      }
    }
    if (!run.empty()) runs.push_back(std::move(run));
  }
  return runs;
}

// A loop closes when the path comes back to a point it passed since the last loop closed,
// at least `min_length` of path later.
int count_closed_loops(const std::vector<Point2>& run, double min_length) {
  int loops = 0;
  std::size_t start = 0;
  std::vector<double> along(run.size(), 0);
  for (std::size_t i = 1; i < run.size(); ++i) {
    along[i] = along[i - 1] + std::hypot(run[i].x - run[i - 1].x, run[i].y - run[i - 1].y);
    for (std::size_t j = start; j < i; ++j) {
      if (along[i] - along[j] > min_length && std::hypot(run[i].x - run[j].x, run[i].y - run[j].y) < 1e-2) {
        ++loops;
        start = i;
        break;
      }
    }
  }
  return loops;
}

}  // namespace

StrategyAnalysis analyse_strategy(const Layer& layer) {
  StrategyAnalysis out;
  const double tool_r = layer.tool.diameter / 2;
  const auto runs = level_runs(layer);

  // A helix or circles about one centre with one radius: a hole milled by interpolation.
  if (!layer.arcs.empty()) {
    double arc_length = 0, total = 0;
    for (const auto& a : layer.arcs) arc_length += std::abs(a.sweep) * a.radius;
    for (const auto& path : layer.paths) {
      for (std::size_t i = 1; i < path.size(); ++i) total += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
    }
    const auto& first = layer.arcs.front();
    bool same = true;
    double turned = 0;
    for (const auto& a : layer.arcs) {
      same = same && std::hypot(a.center.x - first.center.x, a.center.y - first.center.y) < 0.01 &&
             std::abs(a.radius - first.radius) < 0.01;
      turned += a.sweep;
    }
    if (same && total > 0 && arc_length > 0.9 * total && std::abs(turned) >= 2 * std::numbers::pi - 1e-3) {
      out.single_circle = true;
      out.circle_center = first.center;
      out.circle_radius = first.radius;
      out.strategy = Strategy::Helical;
      return out;
    }
  }

  std::vector<Straight> straights;
  double total = 0;
  for (const auto& run : runs) {
    for (std::size_t i = 1; i < run.size(); ++i) {
      Straight s{run[i - 1], run[i]};
      total += s.length();
      if (s.length() > 1e-6) straights.push_back(s);
    }
  }
  if (total <= 0) {
    out.strategy = Strategy::Plunge;
    return out;
  }
  for (const auto& run : runs) out.closed_loops += count_closed_loops(run, 4 * std::max(tool_r, 0.5));

  // Direction histogram of the long straight moves (1° bins, direction modulo 180°).
  std::map<int, double> bins;
  for (const auto& s : straights) {
    if (s.length() < tool_r) continue;
    double deg = std::atan2(s.b.y - s.a.y, s.b.x - s.a.x) * 180 / std::numbers::pi;
    if (deg < 0) deg += 180;
    bins[static_cast<int>(std::lround(deg)) % 180] += s.length();
  }
  int dominant = -1;
  double dominant_length = 0;
  for (const auto& [deg, len] : bins) {
    const double around = len + (bins.count((deg + 1) % 180) ? bins[(deg + 1) % 180] : 0) +
                          (bins.count((deg + 179) % 180) ? bins[(deg + 179) % 180] : 0);
    if (around > dominant_length) dominant_length = around, dominant = deg;
  }
  const bool parallel = dominant >= 0 && dominant_length > 0.6 * total;

  if (parallel) {
    // Parallel passes sweep across the area: the offsets of successive passes move one way.
    // Nested contours have long parallel sides too, but their offsets jump from side to side.
    const double ux = std::cos(dominant * std::numbers::pi / 180), uy = std::sin(dominant * std::numbers::pi / 180);
    int forward = 0, backward = 0;
    std::vector<double> sequence;
    for (const auto& s : straights) {
      const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
      const double along = (dx * ux + dy * uy) / s.length();
      if (std::abs(along) < std::cos(1.5 * std::numbers::pi / 180) || s.length() < tool_r) continue;
      (along > 0 ? forward : backward)++;
      sequence.push_back(-s.a.x * uy + s.a.y * ux);
    }
    int rising = 0, falling = 0;
    std::vector<double> gaps;
    for (std::size_t i = 1; i < sequence.size(); ++i) {
      const double d = sequence[i] - sequence[i - 1];
      if (std::abs(d) <= 0.05) continue;
      (d > 0 ? rising : falling)++;
      gaps.push_back(std::abs(d));
    }
    const int parallel_moves = forward + backward;
    if (parallel_moves == 1 && out.closed_loops == 0) {
      out.strategy = Strategy::CenterMilling;  // one straight pass: a slot along its centre line
      return out;
    }
    const bool sweeping = parallel_moves >= 3 && std::max(rising, falling) >= 0.75 * (rising + falling);
    if (sweeping) {
      std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
      out.stepover = gaps.empty() ? 0 : gaps[gaps.size() / 2];
      out.strategy = std::min(forward, backward) >= std::max(1, parallel_moves / 4) ? Strategy::Bidirectional
                                                                                    : Strategy::Unidirectional;
      return out;
    }
  }

  // Many separate passes at one level, or mostly short curved moves: adaptive clearing.
  if (layer.paths.size() >= 4 && out.closed_loops <= 1) {
    out.strategy = Strategy::Adaptive;
    return out;
  }
  if (out.closed_loops >= 2) {
    out.strategy = Strategy::ContourParallel;
  } else if (out.closed_loops == 1) {
    out.strategy = Strategy::Contour;
  } else {
    // An open path that neither closes nor runs parallel: a centre line when it sweeps one
    // tool width along its whole length (it never overlaps itself), else a spiral.
    double length = 0;
    for (const auto& run : runs) {
      for (std::size_t i = 1; i < run.size(); ++i) length += std::hypot(run[i].x - run[i - 1].x, run[i].y - run[i - 1].y);
    }
    const double one_width = length * 2 * tool_r + std::numbers::pi * tool_r * tool_r;
    const double swept = layer.area.area();
    const bool center_line = swept <= 1.05 * one_width && swept >= 0.9 * one_width;
    out.strategy = center_line ? Strategy::CenterMilling : Strategy::ContourSpiral;
  }
  return out;
}

}  // namespace ncbridge::feature_recognizer
