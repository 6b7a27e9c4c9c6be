#include "ncbridge/feature_recognizer/recognizer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>

#include "cutting_layers.hpp"
#include "feature_classification.hpp"
#include "feature_grouping.hpp"
#include "box_index.hpp"
#include "hole_recognition.hpp"
#include "material_model.hpp"
#include "swept_area.hpp"
#include "work_budget.hpp"

namespace ncbridge::feature_recognizer {
namespace {

// Step-down layers repeat the same XY path: their swept region is computed once. A layer's key
// is its tool and its XY paths relative to their first point, rounded to 0.1 µm: a path repeated
// elsewhere (a pattern of equal pockets, step-downs) has the same key, and its swept area is the
// cached one moved. The cache holds a hash of the key and the layer it was made for, whose key
// is compared in full on a hit (no copy of every path's coordinates is kept).
Point2 path_origin(const Layer& layer) {
  for (const auto& path : layer.paths) {
    if (!path.empty()) return {path.front().x, path.front().y};
  }
  return {};
}

template <typename Visit>
void visit_key(const Layer& layer, Point2 origin, Visit visit) {
  visit(std::llround(layer.tool.diameter * 1e4));
  for (const auto& path : layer.paths) {
    for (const auto& p : path) {
      visit(std::llround((p.x - origin.x) * 1e4));
      visit(std::llround((p.y - origin.y) * 1e4));
    }
    visit(-(1LL << 62));  // path separator
  }
}

std::uint64_t key_hash(const Layer& layer, Point2 origin) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  visit_key(layer, origin, [&](long long v) { h = (h ^ static_cast<std::uint64_t>(v)) * 0x100000001b3ull; });
  return h;
}

bool same_key(const Layer& a, Point2 a_origin, const Layer& b, Point2 b_origin) {
  std::vector<long long> ka, kb;
  visit_key(a, a_origin, [&](long long v) { ka.push_back(v); });
  visit_key(b, b_origin, [&](long long v) { kb.push_back(v); });
  return ka == kb;
}

// A layer whose path box overlaps those of more than this many of the latest 4 x as many earlier
// layers of other paths near it, each box at least a quarter of its own (step-downs repeating one
// path count once; a late profile around many small pockets is no crowd) is in a crowd: no real part cuts one place with so
// many different paths, a program of random strokes across the part soon does, and there every
// exact comparison costs as much as the layer itself (docs/recognition.md, "Bounded cost").
constexpr std::size_t kCrowdedLayers = 128;

// Past the budget (the path points and area vertices of the layers made so far), or in a crowd,
// the layers are coarse: no swept area.
void compute_layer_areas(std::vector<Layer>& layers, double tolerance, WorkBudget& budget,
                         const std::function<void()>& checkpoint) {
  std::unordered_multimap<std::uint64_t, std::size_t> cache;  // key hash -> the layer whose area it is
  BoxIndex paths_by_box(kIndexCell);  // the layers of distinct paths, by their paths' boxes
  for (std::size_t i = 0; i < layers.size(); ++i) {
    if (checkpoint) checkpoint();
    auto& layer = layers[i];
    if (!budget.available() || layer.coarse) {
      layer.coarse = true;
      continue;
    }
    const Point2 origin = path_origin(layer);
    const auto hash = key_hash(layer, origin);
    std::optional<std::size_t> made;
    for (auto [it, end] = cache.equal_range(hash); it != end && !made; ++it) {
      if (same_key(layers[it->second], path_origin(layers[it->second]), layer, origin)) made = it->second;
    }
    if (!made) {
      std::size_t crowd = 0;
      const double size = layer.extent.width() * layer.extent.height();
      for (auto k : paths_by_box.latest(layer.extent, 4 * kCrowdedLayers)) {
        const Box2& other = layers[k].extent;
        crowd += boxes_overlap(other, layer.extent) && other.width() * other.height() >= 0.25 * size ? 1 : 0;
      }
      paths_by_box.insert(i, layer.extent);
      if (crowd > kCrowdedLayers) {
        layer.coarse = true;
        continue;
      }
    }
    if (made) {
      const Point2 made_at = path_origin(layers[*made]);
      const auto& area = layers[*made].area;
      layer.area = made_at == origin ? area : area.translated(origin.x - made_at.x, origin.y - made_at.y);
    } else {
      const WorkCharge charge(budget);
      layer.area = swept_area(layer.xy_paths(), layer.tool.diameter / 2, tolerance);
      cache.emplace(hash, i);
    }
    if (auto box = layer.area.bbox()) layer.extent = *box;
  }
}

// Area, fill, floor and order of a group from its operations' layers.
void rebuild(MillingGroup& group, const std::vector<Layer>& layers) {
  group.area = Region();
  group.filled = Region();
  group.floor = 1e300;
  bool first = true;
  for (auto i : group.layers()) {
    const auto& l = layers[i];
    group.area = group.area.united(l.area);
    group.filled = group.filled.united(l.area.filled());
    group.floor = std::min(group.floor, l.z);
    if (first || l.sequence < group.sequence) {
      group.sequence = l.sequence;
      group.first_workingstep = l.workingsteps.front();
      first = false;
    }
  }
}

double box_area(const Box2& b) { return std::max(0.0, b.width()) * std::max(0.0, b.height()); }

// A step-down onto a clearly smaller area than the layer before it (its extent and its filled
// area less than 80 % of that layer's) is a pocket nested in the floor, cut right after with the
// same tool: it and the rest of that operation become their own group, with the later
// operations that go below the outer floor.
void split_nested_step_downs(std::vector<MillingGroup>& groups, const std::vector<Layer>& layers) {
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (groups[g].freeform || groups[g].coarse) continue;
    for (std::size_t k = 0; k < groups[g].operations.size(); ++k) {
      auto& op = groups[g].operations[k];
      std::size_t split = 0;
      for (std::size_t j = 1; j < op.layers.size() && split == 0; ++j) {
        const auto& prev = layers[op.layers[j - 1]];
        const auto& cur = layers[op.layers[j]];
        if (cur.area.same_as(prev.area) || cur.z >= prev.z - 1e-3) continue;
        if (box_area(cur.extent) >= 0.8 * box_area(prev.extent)) continue;
        if (cur.area.filled().area() < 0.8 * prev.area.filled().area()) split = j;
      }
      if (split == 0) continue;
      MillingGroup inner;
      inner.freeform = false;
      inner.operations.push_back({{op.layers.begin() + static_cast<std::ptrdiff_t>(split), op.layers.end()}, op.tool_number});
      op.layers.resize(split);
      auto& outer = groups[g];
      rebuild(outer, layers);
      for (std::size_t m = k + 1; m < outer.operations.size();) {
        double lowest = 1e300;
        for (auto i : outer.operations[m].layers) lowest = std::min(lowest, layers[i].z);
        if (lowest < outer.floor - 1e-3) {
          inner.operations.push_back(std::move(outer.operations[m]));
          outer.operations.erase(outer.operations.begin() + static_cast<std::ptrdiff_t>(m));
        } else {
          ++m;
        }
      }
      rebuild(outer, layers);
      rebuild(inner, layers);
      groups.push_back(std::move(inner));  // looked at in turn: it may hold a nesting too
      break;
    }
  }
}

Region disk(Point2 c, double diameter, double tolerance) { return Region::polygon(stadium(c, c, diameter / 2, tolerance)); }

// mm: a cut no deeper into the material than this removes nothing.
constexpr double kAirCut = 1e-6;

struct Pending {
  std::size_t order;
  ClassifiedFeature item;
  Region cut;           // what it removes, for the material model
  bool is_hole = false;
  Point2 hole_at;
};

}  // namespace

std::vector<RecognizedFeature> recognize(const std::vector<ToolpathWorkingstep>& workingsteps,
                                         const setup::Stock& stock, const Options& options) {
  const auto& checkpoint = options.checkpoint;
  auto analysis = analyse_cutter_locations(workingsteps, options.chord_tolerance, checkpoint);
  // One budget per stage (docs/recognition.md, "Bounded cost"), in proportion to the program.
  double points = static_cast<double>(analysis.drill_passes.size());
  for (const auto& layer : analysis.layers) {
    for (const auto& path : layer.paths) points += static_cast<double>(path.size());
  }
  const double limit = options.work_per_point > 0 ? options.work_base + options.work_per_point * points
                                                  : std::numeric_limits<double>::infinity();
  WorkBudget areas_budget(limit), grouping_budget(limit), classification_budget(limit), material_budget(limit);
  compute_layer_areas(analysis.layers, options.chord_tolerance, areas_budget, checkpoint);
  auto groups = group_layers(analysis.layers, options.finishing_allowance, grouping_budget, checkpoint);
  split_nested_step_downs(groups, analysis.layers);
  const auto part = find_part_envelope(groups, stock, options.chord_tolerance);

  std::vector<Pending> pending;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (checkpoint) checkpoint();
    if (auto c = classify_group(g, groups, analysis.layers, part, classification_budget)) {
      Pending p{c->order, std::move(*c), groups[g].area};
      pending.push_back(std::move(p));
    }
  }
  for (const auto& hole : recognize_holes(analysis.drill_passes)) {
    if (checkpoint) checkpoint();
    if (!part.outline.contains(hole.at)) continue;  // drilling in the air beside the part
    ClassifiedFeature c;
    auto& f = c.feature;
    f.type = FeatureType::RoundHole;
    f.x = hole.at.x, f.y = hole.at.y;
    f.diameter = hole.diameter;
    f.profile.shape = ProfileShape::Circular;
    f.profile.diameter = hole.diameter;
    // The drill's point breaking out below the part's bottom makes the hole through.
    if (hole.z_bottom < part.bottom_z - 1e-3) {
      f.bottom = BottomCondition::Through;
      f.bottom_z = part.bottom_z;
    } else {
      f.bottom_z = hole.z_bottom;
      f.bottom = hole.point_angle > 0 ? BottomCondition::Conical : BottomCondition::Planar;
      f.bottom_angle_deg = hole.point_angle;
    }
    f.operations = hole.operations;
    c.order = hole.sequence;
    Pending p{c.order, c, disk(hole.at, hole.diameter, options.chord_tolerance)};
    p.is_hole = true;
    p.hole_at = hole.at;
    pending.push_back(std::move(p));
  }
  std::stable_sort(pending.begin(), pending.end(), [](const Pending& a, const Pending& b) { return a.order < b.order; });

  MaterialModel material(stock.max[2]);
  std::vector<RecognizedFeature> out;
  for (auto& p : pending) {
    if (checkpoint) checkpoint();
    auto& f = p.item.feature;
    if (!material_budget.available()) {
      f.top_z = stock.max[2];  // not compared with the earlier cuts (beyond the work limit)
      f.approximate = true;
    } else {
      const WorkCharge charge(material_budget);
      f.top_z = p.is_hole ? material.height_at(p.hole_at, p.order) : material.top_over(p.item.footprint, f.bottom_z, p.order);
    }
    // Cut at or above the material (feeds above the stock, a contour at the stock's top): air,
    // no feature. Its workingsteps stay in the model as the toolpaths they are.
    if (f.bottom_z >= f.top_z - kAirCut) continue;
    material.add_cut(p.cut, f.bottom_z, p.order);
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace ncbridge::feature_recognizer
