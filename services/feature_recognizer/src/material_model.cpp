#include "material_model.hpp"

#include <algorithm>

namespace ncbridge::feature_recognizer {

void MaterialModel::add_cut(const Region& area, double floor, std::size_t order) {
  cuts_.push_back({area, floor, order, area.bbox()});
  if (cuts_.back().box) index_.insert(cuts_.size() - 1, *cuts_.back().box);
}

std::vector<const MaterialModel::Cut*> MaterialModel::cuts_near(const Box2& box) const {
  std::vector<const Cut*> out;
  for (auto i : index_.candidates(box)) out.push_back(&cuts_[i]);
  return out;
}

double MaterialModel::height_at(Point2 p, std::size_t order) const {
  double h = stock_top_;
  for (const Cut* cut : cuts_near({p.x, p.y, p.x, p.y})) {
    if (cut->order < order && cut->floor < h && cut->box && p.x >= cut->box->xmin && p.x <= cut->box->xmax &&
        p.y >= cut->box->ymin && p.y <= cut->box->ymax && cut->area.contains(p)) {
      h = cut->floor;
    }
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
  for (const Cut* cut : cuts_near(*box)) {
    if (cut->order < order && boxes_overlap(box, cut->box)) near.push_back(cut);
  }
  std::vector<double> levels{stock_top_};
  for (const Cut* cut : near) {
    if (cut->floor > floor + 1e-3 && cut->floor < stock_top_) levels.push_back(cut->floor);
  }
  std::sort(levels.begin(), levels.end(), std::greater<>());
  levels.erase(std::unique(levels.begin(), levels.end(), [](double a, double b) { return std::abs(a - b) < 1e-6; }),
               levels.end());
  for (double level : levels) {
    // Where material still stands at `level`: not inside any earlier cut whose floor is lower.
    Region standing = area;
    for (const Cut* cut : near) {
      if (cut->floor < level - 1e-6) standing = standing.minus(cut->area);
    }
    if (standing.area() >= share * total) return level;
  }
  return levels.back();
}

}  // namespace ncbridge::feature_recognizer
