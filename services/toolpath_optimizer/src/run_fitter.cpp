// fit_polyline: greedy segmentation of a run into the longest line or arc from each vertex, then
// short moves folded (short_move_folding.cpp).
#include <algorithm>
#include <cmath>

#include "fitting.hpp"
#include "ncbridge/toolpath_optimizer/fit.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"

namespace ncbridge::toolpath_optimizer {

bool extrusion_rate_fits(std::span<const FitVertex> v, std::size_t first, std::size_t last, double variance) {
  const double length = v[last].along - v[first].along;
  const double filament = v[last].e - v[first].e;
  if (filament == 0) {
    for (std::size_t i = first + 1; i <= last; ++i) {
      if (v[i].e != v[i - 1].e) return false;
    }
    return true;
  }
  if (length <= 0) return false;
  const double mean = filament / length;
  const double lo = mean * (1 - variance), hi = mean * (1 + variance);
  for (std::size_t i = first + 1; i <= last; ++i) {
    const double l = v[i].along - v[i - 1].along;
    if (l <= 0) return false;
    const double rate = (v[i].e - v[i - 1].e) / l;
    if (rate < std::min(lo, hi) || rate > std::max(lo, hi)) return false;
  }
  return true;
}

namespace {

// The largest k > first for which ok(k) holds, trying k one by one for short spans and then in
// growing strides with a binary search back from the first failure. A few failures in a row are
// tolerated (a circle can fail at three points and hold at five).
template <typename Ok>
std::size_t extend(std::size_t first, std::size_t begin, std::size_t n, std::size_t none, Ok&& ok) {
  std::size_t best = none;
  std::size_t k = begin, step = 1;
  int misses = 0;
  while (k < n) {
    if (ok(k)) {
      best = k;
      misses = 0;
      if (k == n - 1) break;
      if (k - first >= 32) step = std::min<std::size_t>(step * 2, 1024);
      k = std::min(k + step, n - 1);
      continue;
    }
    if (step > 1) {
      std::size_t lo = best, hi = k;
      while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (ok(mid)) lo = mid;
        else hi = mid;
      }
      return lo;
    }
    if (++misses > 3) break;
    ++k;
  }
  return best;
}

}  // namespace

void fit_polyline(std::span<const FitVertex> v, const FitOptions& options, std::vector<FittedMove>& out,
                  FitStats& stats) {
  FitWorkspace workspace;
  fit_polyline(v, options, out, stats, workspace);
}

void fit_polyline(std::span<const FitVertex> v, const FitOptions& options, std::vector<FittedMove>& out,
                  FitStats& stats, FitWorkspace& workspace) {
  const std::size_t n = v.size();
  workspace.valid = false;  // other vertices than last time
  if (n < 2) return;
  const std::size_t begin_out = out.size();
  const double tol = options.tolerance - options.margin;
  std::size_t s = 0;
  while (s + 1 < n) {
    auto line_ok = [&](std::size_t k) {
      return extrusion_rate_fits(v, s, k, options.extrusion_rate_variance) && line_fits(v, s, k, tol);
    };
    const std::size_t line_end = extend(s, s + 2, n, s + 1, line_ok);
    std::size_t arc_end = s;
    ArcGeometry best_arc;
    if (options.arcs && s + 2 < n) {
      ArcGeometry g;
      auto arc_ok = [&](std::size_t k) {
        if (!extrusion_rate_fits(v, s, k, options.extrusion_rate_variance)) return false;
        if (!arc_fits(v, s, k, options, g, workspace)) return false;
        best_arc = g;
        return true;
      };
      // Look for arcs only where they would beat the line.
      arc_end = extend(s, std::max(s + 2, line_end + 1), n, s, arc_ok);
    }
    FittedMove m;
    m.first = s;
    if (arc_end > line_end) {
      m.last = arc_end;
      m.arc = true;
      m.geometry = best_arc;
    } else {
      m.last = line_end;
    }
    out.push_back(m);
    s = m.last;
  }
  fold_short_moves(v, options, out, begin_out, stats);
  for (std::size_t i = begin_out; i < out.size(); ++i) {
    if (out[i].arc) ++stats.arcs;
    else if (out[i].last > out[i].first + 1) ++stats.lines_merged;
  }
}

}  // namespace ncbridge::toolpath_optimizer
