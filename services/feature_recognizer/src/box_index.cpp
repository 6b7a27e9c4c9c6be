#include "box_index.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

namespace ncbridge::feature_recognizer {
namespace {

constexpr std::size_t kLevels = 12;  // the coarsest cells 4^11 times the finest
constexpr long long kMaxCellsPerQuery = 1024;

// Files `id` in an ascending list of unique ids (usually at its end: ids are filed in order).
void file(std::vector<std::size_t>& ids, std::size_t id) {
  if (ids.empty() || ids.back() < id) {
    ids.push_back(id);
    return;
  }
  const auto at = std::lower_bound(ids.begin(), ids.end(), id);
  if (at == ids.end() || *at != id) ids.insert(at, id);
}

}  // namespace

bool BoxIndex::cell_range(const Box2& box, std::size_t level, long long max_cells, Cell& lo, Cell& hi) const {
  const double cell = cell_ * std::pow(4.0, static_cast<double>(level));
  // Widened by a hair so a box whose edge falls on a cell line is filed on both sides of it.
  const double pad = 1e-9 * cell + 1e-9;
  const double bounds[4] = {(box.xmin - pad) / cell, (box.ymin - pad) / cell, (box.xmax + pad) / cell,
                            (box.ymax + pad) / cell};
  for (double b : bounds) {
    if (!std::isfinite(b) || std::abs(b) > 1e12) return false;
  }
  lo = {static_cast<long long>(std::floor(bounds[0])), static_cast<long long>(std::floor(bounds[1]))};
  hi = {static_cast<long long>(std::floor(bounds[2])), static_cast<long long>(std::floor(bounds[3]))};
  const long long columns = hi.first - lo.first + 1, rows = hi.second - lo.second + 1;
  return columns <= max_cells && rows <= max_cells && columns * rows <= max_cells;
}

void BoxIndex::insert(std::size_t id, const Box2& box) {
  Cell lo, hi;
  for (std::size_t level = 0; level < kLevels; ++level) {
    if (!cell_range(box, level, 4, lo, hi)) continue;
    if (levels_.size() <= level) levels_.resize(level + 1);
    for (long long x = lo.first; x <= hi.first; ++x) {
      for (long long y = lo.second; y <= hi.second; ++y) file(levels_[level][{x, y}], id);
    }
    return;
  }
  file(wide_, id);
}

std::vector<std::size_t> BoxIndex::latest(const Box2& box, std::size_t limit) const {
  // The lists the box reads, merged from their ends: the highest ids first, each once.
  std::vector<const std::vector<std::size_t>*> lists{&wide_};
  for (std::size_t level = 0; level < levels_.size(); ++level) {
    const auto& cells = levels_[level];
    Cell lo, hi;
    if (!cell_range(box, level, kMaxCellsPerQuery, lo, hi)) {
      for (const auto& [cell, ids] : cells) lists.push_back(&ids);
      continue;
    }
    for (long long x = lo.first; x <= hi.first; ++x) {
      for (long long y = lo.second; y <= hi.second; ++y) {
        auto it = cells.find({x, y});
        if (it != cells.end()) lists.push_back(&it->second);
      }
    }
  }
  using Head = std::pair<std::size_t, std::size_t>;  // (id, list), the list read down to that id
  std::priority_queue<Head> heads;
  std::vector<std::size_t> next(lists.size());
  for (std::size_t l = 0; l < lists.size(); ++l) {
    next[l] = lists[l]->size();
    if (next[l] > 0) heads.push({(*lists[l])[--next[l]], l});
  }
  std::vector<std::size_t> out;
  while (!heads.empty() && out.size() < limit) {
    const auto [id, l] = heads.top();
    heads.pop();
    if (out.empty() || out.back() != id) out.push_back(id);
    if (next[l] > 0) heads.push({(*lists[l])[--next[l]], l});
  }
  return out;
}

std::vector<std::size_t> BoxIndex::candidates(const Box2& box) const {
  auto out = latest(box, std::numeric_limits<std::size_t>::max());
  std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace ncbridge::feature_recognizer
