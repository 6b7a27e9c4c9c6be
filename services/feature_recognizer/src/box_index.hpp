#pragma once
// Which of many boxes may overlap a given one: boxes are filed in the cells of uniform grids
// they cover, so a query reads a few cells instead of every box. Large programs recognise
// thousands of features, and comparing each with every earlier one grew quadratically. Grids
// of cells 1, 4, 16, ... times the cell size: a box is filed in the finest one where it covers
// at most 2 x 2 cells, so a box over the whole part is in a few cells, not in every one.
#include <cstddef>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "region.hpp"

namespace ncbridge::feature_recognizer {

class BoxIndex {
 public:
  explicit BoxIndex(double cell_size) : cell_(cell_size) {}

  // Files `id` under `box`; filing an id again under a larger box (a growing feature) is fine.
  void insert(std::size_t id, const Box2& box);

  // Every id filed under a box that touches or overlaps `box` (and maybe a few more), ascending
  // and unique: callers still test the boxes themselves.
  std::vector<std::size_t> candidates(const Box2& box) const;

  // The same ids, the highest (the latest filed, for callers that file in machining order)
  // first, at most `limit` of them: a query over a crowded area reads `limit` ids of each cell it
  // covers, not every id filed there.
  std::vector<std::size_t> latest(const Box2& box, std::size_t limit) const;

 private:
  using Cell = std::pair<long long, long long>;
  // The cells of grid `level` that `box` covers; false: too many (over `max_cells`).
  bool cell_range(const Box2& box, std::size_t level, long long max_cells, Cell& lo, Cell& hi) const;
  double cell_;
  std::vector<std::map<Cell, std::vector<std::size_t>>> levels_;  // cells' ids, each ascending and unique
  std::vector<std::size_t> wide_;  // boxes over too many cells to file: always candidates (ascending, unique)
};

}  // namespace ncbridge::feature_recognizer
