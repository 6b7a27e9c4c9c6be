#pragma once
// Phase 2: a group of layers becomes a feature by its cutting area and milling strategy,
// compared with the part's outline: all of the top (planar face), around the part (general
// outside profile), a whole side (step), part of a side (open pocket), across between two
// opposite sides with constant width (through slot), or enclosed (closed pocket, closed slot,
// round hole milled by helix or circles).
#include <optional>
#include <vector>

#include "box_index.hpp"
#include "feature_grouping.hpp"
#include "work_budget.hpp"
#include "ncbridge/setup/stock.hpp"

namespace ncbridge::feature_recognizer {

// The part's extent in XY: the stock block, inside every outside profile.
struct PartEnvelope {
  Region stock;         // the stock block's outline
  Region outline;
  Box2 box;
  Region outside_band;  // a thin band just outside `outline`: cuts reaching it are open there
  double bottom_z = 0;  // the stock's bottom, or the deepest outside profile's floor
  std::vector<std::size_t> outside_profiles;  // indices of the groups that cut around the part
  BoxIndex groups_by_box{25.0};  // every group by its area's box: the groups near one, quickly
};

// Half-width of the band that tells open boundaries (mm).
inline constexpr double kOpenBandWidth = 0.5;
// How far inside the outline the band begins (mm): more than the chord tolerance of the swept
// areas, less than any wall a part keeps.
inline constexpr double kOpenEdgeInset = 0.05;

PartEnvelope find_part_envelope(const std::vector<MillingGroup>& groups, const setup::Stock& stock,
                                double tolerance);

struct ClassifiedFeature {
  RecognizedFeature feature;
  Region footprint;  // the feature's area inside the part, for its top level
  std::size_t order = 0;  // machining order: the sequence number of its first pass
};

// nullopt when the group cut only outside the part (air). The comparisons with other features
// (what earlier ones removed at its edge, the island test) charge `budget`; past it they are
// left out and the feature is marked approximate. A coarse group is a `region` of its box.
std::optional<ClassifiedFeature> classify_group(std::size_t group_index, const std::vector<MillingGroup>& groups,
                                                const std::vector<Layer>& layers, const PartEnvelope& part,
                                                WorkBudget& budget);

}  // namespace ncbridge::feature_recognizer
