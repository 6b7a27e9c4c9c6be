#pragma once
// What the generator knows about the part while it walks the workplan: the stock, the regions
// the CC2 features remove (the finished part is the stock less all of them), and what the
// operations generated so far have cut (in-process material), as polygons.
#include <cstddef>
#include <map>
#include <vector>

#include "ncbridge/material_check/feature_region.hpp"
#include "ncbridge/stepnc/features.hpp"
#include "planar_paths.hpp"

namespace ncbridge::toolpath_generator {

struct ShapedFeature {
  material_check::FeatureRegion region;
  const stepnc::Feature* cc2 = nullptr;  // the feature it is made from
  PolygonSet area;       // the region
  PolygonSet open_side;  // beyond the open edges it declares, where the cutter may run out
  material_check::Box2 box;
};

class PartModel {
 public:
  PartModel(const setup::Stock& stock, std::vector<ShapedFeature> features);

  const setup::Stock& stock() const { return stock_; }
  // The feature of project.features[index]; nullptr when it is not one with geometry.
  const ShapedFeature* feature(std::size_t index) const;
  const std::vector<ShapedFeature>& features() const { return features_; }

  // Where the cutter may be at height `z` (the floor it cuts to) near feature `f` without
  // cutting the finished part: f's area and open side, every feature whose floor is at or below
  // z, and everything outside the stock; within `near` mm of f's area.
  PolygonSet free_space(const ShapedFeature& f, double z, double near) const;

  // In-process material: after an operation, the area it cut down to `z`.
  void record_cut(const PolygonSet& area, double z);
  // Everything cut down to `z` or deeper so far (and outside the stock), near `box`.
  PolygonSet cleared_at(double z, const material_check::Box2& box) const;
  // The highest material under a disk of `radius` about p: the stock's top, lower where the disk
  // lies wholly in what is cleared; -infinity outside the stock.
  double material_top(Point2 p, double radius) const;

  // The stock's outside (a wide frame about it).
  const PolygonSet& outside_stock() const { return outside_; }

 private:
  struct Cut {
    PolygonSet area;
    double z;
    material_check::Box2 box;
  };
  setup::Stock stock_;
  std::vector<ShapedFeature> features_;
  std::map<std::size_t, std::size_t> by_index_;
  std::vector<Cut> cuts_;
  PolygonSet outside_;
};

bool boxes_meet(const material_check::Box2& a, const material_check::Box2& b, double margin = 0);
material_check::Box2 grown(const material_check::Box2& b, double margin);

}  // namespace ncbridge::toolpath_generator
