#include "box_index.hpp"

#include <algorithm>
#include <cmath>

namespace ncbridge::feature_recognizer {
namespace {

constexpr long long kMaxCellsPerBox = 256;

}  // namespace

bool BoxIndex::cell_range(const Box2& box, Cell& lo, Cell& hi) const {
  // Widened by a hair so a box whose edge falls on a cell line is filed on both sides of it.
  const double pad = 1e-9 * cell_ + 1e-9;
  const double bounds[4] = {(box.xmin - pad) / cell_, (box.ymin - pad) / cell_, (box.xmax + pad) / cell_,
                            (box.ymax + pad) / cell_};
  for (double b : bounds) {
    if (!std::isfinite(b) || std::abs(b) > 1e12) return false;
  }
  lo = {static_cast<long long>(std::floor(bounds[0])), static_cast<long long>(std::floor(bounds[1]))};
  hi = {static_cast<long long>(std::floor(bounds[2])), static_cast<long long>(std::floor(bounds[3]))};
  const long long columns = hi.first - lo.first + 1, rows = hi.second - lo.second + 1;
  return columns <= kMaxCellsPerBox && rows <= kMaxCellsPerBox && columns * rows <= kMaxCellsPerBox;
}

void BoxIndex::insert(std::size_t id, const Box2& box) {
  Cell lo, hi;
  if (!cell_range(box, lo, hi)) {
    wide_.push_back(id);
    return;
  }
  for (long long x = lo.first; x <= hi.first; ++x) {
    for (long long y = lo.second; y <= hi.second; ++y) {
      auto& ids = cells_[{x, y}];
      if (ids.empty() || ids.back() != id) ids.push_back(id);
    }
  }
}

std::vector<std::size_t> BoxIndex::candidates(const Box2& box) const {
  std::vector<std::size_t> out(wide_);
  Cell lo, hi;
  if (!cell_range(box, lo, hi)) {
    for (const auto& [cell, ids] : cells_) out.insert(out.end(), ids.begin(), ids.end());
  } else {
    for (long long x = lo.first; x <= hi.first; ++x) {
      for (long long y = lo.second; y <= hi.second; ++y) {
        auto it = cells_.find({x, y});
        if (it != cells_.end()) out.insert(out.end(), it->second.begin(), it->second.end());
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace ncbridge::feature_recognizer
