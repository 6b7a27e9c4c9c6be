#include "material_model.hpp"

#include <algorithm>

namespace ncbridge::feature_recognizer {

void MaterialModel::add_cut(const Region& area, double floor, std::size_t order) {
  cuts_.push_back({area, floor, order, area.bbox()});
  if (cuts_.back().box) index_.insert(cuts_.size() - 1, *cuts_.back().box);
}

std::vector<const MaterialModel::Cut*> MaterialModel::cuts_near(const Box2& box, std::size_t order) const {
  std::vector<const Cut*> out;
  for (auto i : index_.latest(box, kNearCandidateLimit)) {
    const Cut& cut = cuts_[i];
    if (cut.order < order && cut.box && box.xmin <= cut.box->xmax && cut.box->xmin <= box.xmax &&
        box.ymin <= cut.box->ymax && cut.box->ymin <= box.ymax) {
      out.push_back(&cut);
    }
  }
  std::reverse(out.begin(), out.end());
  return out;
}

namespace {

// The latest near_feature_limit of `cuts` (bounded exact work), in the order they were made.
template <typename Cut>
void keep_latest(std::vector<const Cut*>& cuts) {
  const std::size_t limit = near_feature_limit(cuts.size());
  if (cuts.size() <= limit) return;
  std::stable_sort(cuts.begin(), cuts.end(), [](const Cut* a, const Cut* b) { return a->order > b->order; });
  cuts.resize(limit);
  std::stable_sort(cuts.begin(), cuts.end(), [](const Cut* a, const Cut* b) { return a->order < b->order; });
}

}  // namespace

double MaterialModel::height_at(Point2 p, std::size_t order) const {
  double h = stock_top_;
  auto near = cuts_near({p.x, p.y, p.x, p.y}, order);
  keep_latest(near);
  for (const Cut* cut : near) {
    if (cut->floor < h && cut->area.contains(p)) h = cut->floor;
  }
  return h;
}

double MaterialModel::top_over(const Region& area, double floor, std::size_t order, double share) const {
  const double total = area.area();
  if (total <= 0) return stock_top_;
  // Only cuts whose box meets the area's can lower material over it (and a level from a cut
  // elsewhere would leave the same standing region as the next higher level: no new answer).
  const auto box = area.bbox();
  std::vector<const Cut*> near;
  for (const Cut* cut : cuts_near(*box, order)) {
    if (boxes_overlap(box, cut->box)) near.push_back(cut);
  }
  keep_latest(near);
  std::vector<double> levels{stock_top_};
  for (const Cut* cut : near) {
    if (cut->floor > floor + 1e-3 && cut->floor < stock_top_) levels.push_back(cut->floor);
  }
  std::sort(levels.begin(), levels.end(), std::greater<>());
  levels.erase(std::unique(levels.begin(), levels.end(), [](double a, double b) { return std::abs(a - b) < 1e-6; }),
               levels.end());
  // Where material still stands at `level`: not inside any earlier cut whose floor is lower. The
  // standing area shrinks as the level rises, so the answer is the highest level where it is
  // still `share` of the area: the stock's top when it is (usually: one pass over the cuts),
  // else found from the lowest level up, adding the cuts below each level once.
  Region standing = area;
  for (const Cut* cut : near) {
    if (cut->floor < levels.front() - 1e-6) standing = standing.minus(cut->area);
  }
  if (standing.area() >= share * total || levels.size() == 1) return levels.front();
  std::vector<const Cut*> by_floor = near;
  std::stable_sort(by_floor.begin(), by_floor.end(), [](const Cut* a, const Cut* b) { return a->floor < b->floor; });
  std::size_t next = 0;
  standing = area;
  double answer = levels.back();
  for (auto level = levels.rbegin(); level != levels.rend(); ++level) {
    bool changed = false;
    for (; next < by_floor.size() && by_floor[next]->floor < *level - 1e-6; ++next) {
      standing = standing.minus(by_floor[next]->area);
      changed = true;
    }
    if (changed && standing.area() < share * total) break;
    answer = *level;
  }
  return answer;
}

}  // namespace ncbridge::feature_recognizer
