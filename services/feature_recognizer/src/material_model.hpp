#pragma once
// The material left by earlier workingsteps, as a height field: the stock's top everywhere,
// lowered to each earlier feature's floor inside its cutting area. A feature's top is the
// highest level that material reaches over its own area before it is cut.
#include <vector>

#include "box_index.hpp"
#include "feature_grouping.hpp"
#include "region.hpp"

namespace ncbridge::feature_recognizer {

class MaterialModel {
 public:
  explicit MaterialModel(double stock_top) : stock_top_(stock_top), index_(kCell) {}

  // Records that the area `area` was cut down to `floor` by the cut number `order`.
  void add_cut(const Region& area, double floor, std::size_t order);

  // Height of the material at `p` before cut number `order`.
  double height_at(Point2 p, std::size_t order) const;

  // The highest level that covers at least `share` of `area` before cut number `order`,
  // considering only levels above `floor`; the stock top when nothing was cut there.
  double top_over(const Region& area, double floor, std::size_t order, double share = 0.05) const;

 private:
  struct Cut {
    Region area;
    double floor;
    std::size_t order;
    std::optional<Box2> box;  // of `area`: cuts elsewhere change nothing here
  };
  static constexpr double kCell = 25.0;  // mm, of the index of the cuts' boxes
  // The cuts before `order` whose boxes touch `box` (or contain a point), of the latest
  // kNearCandidateLimit filed near it, in the order they were made.
  std::vector<const Cut*> cuts_near(const Box2& box, std::size_t order) const;
  double stock_top_;
  std::vector<Cut> cuts_;
  BoxIndex index_;
};

}  // namespace ncbridge::feature_recognizer
