// The material model's answers against their definition, computed the slow way: a feature's top
// is the highest level (the stock's top or the floor, above the feature's floor, of an earlier
// cut near it) at which material still stands over at least 5 % of its area, where material
// stands outside every earlier cut whose floor is below that level; the lowest of those levels
// when it stands nowhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "material_model.hpp"
#include "swept_area.hpp"

namespace fr = ncbridge::feature_recognizer;

namespace {

struct Cut {
  fr::Region area;
  double floor;
};

double top_by_definition(const std::vector<Cut>& cuts, const fr::Region& area, double floor, double stock_top) {
  std::vector<double> levels{stock_top};
  for (const auto& c : cuts) {
    if (c.floor > floor + 1e-3 && c.floor < stock_top && fr::boxes_overlap(c.area.bbox(), area.bbox())) {
      levels.push_back(c.floor);
    }
  }
  std::sort(levels.begin(), levels.end(), std::greater<>());
  for (double level : levels) {
    fr::Region standing = area;
    for (const auto& c : cuts) {
      if (c.floor < level - 1e-6) standing = standing.minus(c.area);
    }
    if (standing.area() >= 0.05 * area.area()) return level;
  }
  return levels.back();
}

class Lcg {
 public:
  double next(double hi) {
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state_ >> 33) / static_cast<double>(1ull << 31) * hi;
  }

 private:
  unsigned long long state_ = 42;
};

}  // namespace

TEST(MaterialModel, TopIsTheHighestLevelWithFivePercentStandingAsDefined) {
  // Pockets, slots and faces at random floors over a 100 x 80 plate, each feature's top asked
  // before its own cut is added: every answer equals the definition's (at most 12 cuts, under
  // the bound of exact comparisons).
  Lcg random;
  for (int trial = 0; trial < 20; ++trial) {
    fr::MaterialModel model(0);
    std::vector<Cut> cuts;
    for (std::size_t k = 0; k < 12; ++k) {
      const double x = random.next(80), y = random.next(60), floor = -random.next(10);
      fr::Region area = k % 3 == 0 ? fr::Region::rectangle({x, y, x + 5 + random.next(40), y + 5 + random.next(30)})
                                   : fr::swept_area({{{x, y}, {x + random.next(30), y + random.next(20)}}},
                                                    1 + random.next(6), 0.01);
      const double got = model.top_over(area, floor, k);
      EXPECT_DOUBLE_EQ(got, top_by_definition(cuts, area, floor, 0)) << "trial " << trial << " cut " << k;
      const fr::Point2 centre{x + 2, y + 2};
      double height = 0;
      for (const auto& c : cuts) {
        if (c.area.contains(centre)) height = std::min(height, c.floor);
      }
      EXPECT_DOUBLE_EQ(model.height_at(centre, k), height);
      model.add_cut(area, floor, k);
      cuts.push_back({area, floor});
    }
  }
}

TEST(MaterialModel, OnlyTheLatestCutsNearAFeatureAreComparedExactly) {
  // Forty cuts over the same spot, each deeper: the bound keeps the latest kNearFeatureLimit.
  // The deepest and latest decides the top here, as it does without the bound.
  fr::MaterialModel model(0);
  const auto spot = fr::Region::rectangle({0, 0, 10, 10});
  for (std::size_t k = 0; k < 40; ++k) model.add_cut(spot, -0.5 * static_cast<double>(k + 1), k);
  EXPECT_DOUBLE_EQ(model.top_over(fr::Region::rectangle({2, 2, 8, 8}), -30, 40), -20);
  EXPECT_DOUBLE_EQ(model.height_at({5, 5}, 40), -20);
  // The first cut alone lowered this spot before cut 1.
  EXPECT_DOUBLE_EQ(model.height_at({5, 5}, 1), -0.5);
}

TEST(Region, UnionOfManyIsTheChainedUnion) {
  Lcg random;
  std::vector<fr::Region> parts;
  fr::Region chained;
  for (int k = 0; k < 12; ++k) {
    const double x = random.next(50), y = random.next(50);
    parts.push_back(k % 2 == 0 ? fr::swept_area({{{x, y}, {x + 20, y + 5}, {x + 5, y + 25}, {x, y}}}, 2, 0.01)
                               : fr::Region::rectangle({x, y, x + random.next(20) + 1, y + random.next(20) + 1}));
    chained = chained.united(parts.back());
  }
  const auto all = fr::Region::union_all(parts);
  // Each of the chained unions rounds the crossings it makes to the grid.
  double perimeter = 0;
  for (const auto& p : chained.polygons()) {
    for (const auto* ring : {&p.outer}) {
      for (std::size_t i = 0; i < ring->size(); ++i) {
        perimeter += std::hypot((*ring)[(i + 1) % ring->size()].x - (*ring)[i].x, (*ring)[(i + 1) % ring->size()].y - (*ring)[i].y);
      }
    }
    for (const auto& h : p.holes) {
      for (std::size_t i = 0; i < h.size(); ++i) perimeter += std::hypot(h[(i + 1) % h.size()].x - h[i].x, h[(i + 1) % h.size()].y - h[i].y);
    }
  }
  const double bound = 13 * perimeter * fr::kGrid;
  EXPECT_NEAR(all.area(), chained.area(), bound);
  EXPECT_LT(all.minus(chained).area() + chained.minus(all).area(), 2 * bound);
  std::size_t holes_all = 0, holes_chained = 0;
  for (const auto& p : all.polygons()) holes_all += p.holes.size();
  for (const auto& p : chained.polygons()) holes_chained += p.holes.size();
  EXPECT_EQ(holes_all, holes_chained);
  EXPECT_EQ(all.components().size(), chained.components().size());
}
