#include "feature_grouping.hpp"

#include <algorithm>

#include "box_index.hpp"

namespace ncbridge::feature_recognizer {

std::vector<std::size_t> MillingGroup::layers() const {
  std::vector<std::size_t> out;
  for (const auto& op : operations) out.insert(out.end(), op.layers.begin(), op.layers.end());
  return out;
}

namespace {

// A deeper layer that leaves standing, inside what it surrounds, an area the layer above it cut
// (a face milled over the part, then a contour around the part): no step-down of one clearing,
// but another feature below the first one's floor.
bool leaves_what_was_cut_above(const Layer& above, const Layer& layer, const Region& filled) {
  if (!(layer.z < above.z - 1e-3)) return false;
  const double filled_area = filled.area();
  if (!(filled_area > 1.1 * layer.area.area())) return false;  // surrounds little or nothing
  const Region standing = filled.minus(layer.area);
  const double standing_area = standing.area();
  return standing_area >= 0.1 * filled_area && standing.intersected(above.area).area() > 0.5 * standing_area;
}

}  // namespace

std::vector<MillingGroup> group_layers(const std::vector<Layer>& layers, double finishing_allowance, WorkBudget& budget,
                                       const std::function<void()>& checkpoint) {
  std::vector<MillingGroup> groups;
  std::optional<std::size_t> last_group;  // the group the previous layer went to
  std::vector<Region> fills;
  // Culling before exact overlaps: regions in disjoint boxes share nothing, and
  // area(a ∩ b) / area(a ∪ b) <= min(area) / max(area), so very different sizes cannot match.
  std::vector<std::optional<Box2>> fill_boxes, group_boxes;
  std::vector<double> fill_areas, group_areas;
  fills.reserve(layers.size());
  for (std::size_t i = 0; i < layers.size(); ++i) {
    // A swept area shared with an earlier layer (a step-down) shares its filled area too.
    std::size_t same = i;
    for (std::size_t j = i; j-- > 0 && i - j <= 8;) {
      if (layers[j].area.same_as(layers[i].area)) {
        same = j;
        break;
      }
    }
    fills.push_back(same < i ? fills[same] : layers[i].area.filled());
    fill_boxes.push_back(fills.back().bbox());
    fill_areas.push_back(fills.back().area());
  }
  // Earlier groups by box, so a layer meets the few groups near it, not all of them.
  BoxIndex group_index(kIndexCell);
  auto may_match = [&](std::size_t i, std::size_t g) {
    const double a = fill_areas[i], b = group_areas[g];
    return boxes_overlap(fill_boxes[i], group_boxes[g]) && std::min(a, b) >= kSameFeatureOverlap * std::max(a, b);
  };

  for (std::size_t i = 0; i < layers.size(); ++i) {
    if (checkpoint) checkpoint();
    const auto& layer = layers[i];
    if (layer.coarse) {
      if (groups.empty() || !groups.back().coarse || layers[groups.back().operations.back().layers.back()].tool.number != layer.tool.number) {
        MillingGroup group;
        group.coarse = true;
        group.floor = layer.z;
        group.first_workingstep = layer.workingsteps.front();
        group.sequence = layer.sequence;
        groups.push_back(std::move(group));
        group_boxes.emplace_back();
        group_areas.push_back(0);
      }
      auto& group = groups.back();
      group.operations.push_back({{i}, layer.tool.number});
      group.floor = std::min(group.floor, layer.z);
      last_group.reset();
      continue;
    }
    auto add = [&](std::size_t g, bool new_operation) {
      auto& group = groups[g];
      if (new_operation || group.operations.empty()) group.operations.push_back({{}, layer.tool.number});
      group.operations.back().layers.push_back(i);
      group.area = group.area.united(layer.area);
      group.filled = group.filled.united(fills[i]);
      group_boxes.at(g) = box_union(group_boxes.at(g), fill_boxes[i]);
      if (group_boxes[g]) group_index.insert(g, *group_boxes[g]);
      group_areas.at(g) = group.filled.area();
      group.floor = std::min(group.floor, layer.z);
      last_group = g;
    };
    // Continuing the feature the previous layer cut, with the same tool: a step-down (deeper)
    // or, going back up, a new operation on the same region.
    // Each exact comparison is charged; past the budget a layer starts its own feature.
    auto overlaps = [&](std::size_t g) { return overlap_ratio(fills[i], groups[g].filled) >= kSameFeatureOverlap; };
    const WorkCharge charge(budget);
    if (last_group && budget.available()) {
      auto& group = groups[*last_group];
      const auto& prev = layers[group.operations.back().layers.back()];
      if (prev.tool.number == layer.tool.number && prev.freeform == layer.freeform &&
          may_match(i, *last_group) && overlaps(*last_group) && !leaves_what_was_cut_above(prev, layer, fills[i])) {
        add(*last_group, layer.z > prev.z + 1e-3);
        continue;
      }
    }
    // A later operation on an earlier feature: same region, not deeper than its floor beyond
    // the finishing allowance.
    bool attached = false;
    const auto near = fill_boxes[i] ? group_index.latest(*fill_boxes[i], kNearCandidateLimit) : std::vector<std::size_t>{};
    std::size_t compared = 0;
    const std::size_t compare_limit = near_feature_limit(near.size());
    for (auto it = near.begin(); it != near.end() && compared < compare_limit && budget.available(); ++it) {
      const std::size_t g = *it;
      auto& group = groups[g];
      if (group.freeform != layer.freeform) continue;
      if (layer.z < group.floor - finishing_allowance) continue;
      if (!may_match(i, g)) continue;
      ++compared;
      if (overlaps(g)) {
        add(g, true);
        attached = true;
        break;
      }
    }
    if (attached) continue;
    MillingGroup group;
    group.floor = layer.z;
    group.freeform = layer.freeform;
    group.first_workingstep = layer.workingsteps.front();
    group.sequence = layer.sequence;
    groups.push_back(std::move(group));
    group_boxes.emplace_back();
    group_areas.push_back(0);
    add(groups.size() - 1, true);
  }
  return groups;
}

}  // namespace ncbridge::feature_recognizer
