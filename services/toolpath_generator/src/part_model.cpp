#include "part_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncbridge::toolpath_generator {

bool boxes_meet(const material_check::Box2& a, const material_check::Box2& b, double margin) {
  return !(a.xmin > b.xmax + margin || a.xmax < b.xmin - margin || a.ymin > b.ymax + margin || a.ymax < b.ymin - margin);
}

material_check::Box2 grown(const material_check::Box2& b, double margin) {
  return {b.xmin - margin, b.ymin - margin, b.xmax + margin, b.ymax + margin};
}

PartModel::PartModel(const setup::Stock& stock, std::vector<ShapedFeature> features)
    : stock_(stock), features_(std::move(features)) {
  for (std::size_t k = 0; k < features_.size(); ++k) by_index_[features_[k].region.feature_index] = k;
  const double far = 1e4;
  outside_ = PolygonSet::rectangle({stock.min[0] - far, stock.min[1] - far, stock.max[0] + far, stock.max[1] + far})
                 .minus(PolygonSet::rectangle({stock.min[0], stock.min[1], stock.max[0], stock.max[1]}));
}

const ShapedFeature* PartModel::feature(std::size_t index) const {
  auto it = by_index_.find(index);
  return it == by_index_.end() ? nullptr : &features_[it->second];
}

PolygonSet PartModel::free_space(const ShapedFeature& f, double z, double near) const {
  const material_check::Box2 box = grown(f.box, near);
  PolygonSet free = f.area.united(f.open_side).united(outside_);
  for (const auto& g : features_) {
    if (&g == &f || g.region.floor_z > z + 1e-6 || !boxes_meet(g.box, box)) continue;
    free = free.united(g.area);
  }
  return free.intersected(f.area.offset(near, kArcTolerance));
}

void PartModel::record_cut(const PolygonSet& area, double z) {
  if (area.empty()) return;
  cuts_.push_back({area, z, area.box()});
}

PolygonSet PartModel::cleared_at(double z, const material_check::Box2& box) const {
  PolygonSet out = outside_;
  for (const auto& c : cuts_) {
    if (c.z <= z + 1e-6 && boxes_meet(c.box, box)) out = out.united(c.area);
  }
  return out;
}

double PartModel::material_top(Point2 p, double radius) const {
  const auto& s = stock_;
  if (p.x + radius <= s.min[0] || p.x - radius >= s.max[0] || p.y + radius <= s.min[1] || p.y - radius >= s.max[1]) {
    return -std::numeric_limits<double>::infinity();
  }
  const material_check::Box2 box{p.x - radius, p.y - radius, p.x + radius, p.y + radius};
  std::vector<double> levels;
  for (const auto& c : cuts_) {
    if (boxes_meet(c.box, box)) levels.push_back(c.z);
  }
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  for (double z : levels) {
    if (cleared_at(z, box).offset(-radius + 1e-4, kArcTolerance).contains(p)) return z;
  }
  return s.max[2];
}

}  // namespace ncbridge::toolpath_generator
