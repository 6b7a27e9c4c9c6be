// Short moves: a fitted move shorter than --min-segment is merged with the move before or after
// it when one line or arc can take both without leaving the band.
#include "fitting.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

// One move for vertices first..last, a line if one fits, else an arc.
bool refit(std::span<const FitVertex> v, std::size_t first, std::size_t last, const FitOptions& o, FittedMove& m) {
  if (!extrusion_rate_fits(v, first, last, o.extrusion_rate_variance)) return false;
  m.first = first;
  m.last = last;
  if (line_fits(v, first, last, o.tolerance - o.margin)) {
    m.arc = false;
    return true;
  }
  m.arc = o.arcs && arc_fits(v, first, last, o, m.geometry);
  return m.arc;
}

}  // namespace

void fold_short_moves(std::span<const FitVertex> v, const FitOptions& options, std::vector<FittedMove>& out,
                      std::size_t begin, FitStats& stats) {
  if (options.min_segment <= 0) return;
  std::size_t i = begin;
  while (i < out.size()) {
    const FittedMove& m = out[i];
    const double length = v[m.last].along - v[m.first].along;
    if (length >= options.min_segment || out.size() - begin < 2) {
      ++i;
      continue;
    }
    FittedMove merged;
    if (i > begin && refit(v, out[i - 1].first, m.last, options, merged)) {
      out[i - 1] = merged;
      out.erase(out.begin() + static_cast<std::ptrdiff_t>(i));
      ++stats.folded;
      continue;  // the merged move may still be short: look at it again from its successor
    }
    if (i + 1 < out.size() && refit(v, m.first, out[i + 1].last, options, merged)) {
      out[i] = merged;
      out.erase(out.begin() + static_cast<std::ptrdiff_t>(i) + 1);
      ++stats.folded;
      continue;
    }
    ++i;
  }
}

}  // namespace ncbridge::toolpath_optimizer
