#pragma once
// Phase 1, merging: the layers of one feature (step-downs of a roughing operation, the passes
// of a later finishing operation) are gathered into one group, split into operations.
#include <vector>

#include "cutting_layers.hpp"
#include "work_budget.hpp"

namespace ncbridge::feature_recognizer {

struct LayerOperation {
  std::vector<std::size_t> layers;  // indices into the layer list, in machining order
  int tool_number = 0;
};

struct MillingGroup {
  std::vector<LayerOperation> operations;
  Region area;        // union of the layers' swept regions
  Region filled;      // the same with holes closed
  double floor = 0;   // lowest cutting level
  bool freeform = false;
  bool coarse = false;  // made of coarse layers (beyond the work limit): one run of one tool
  std::size_t first_workingstep = 0;
  std::size_t sequence = 0;  // of its first pass: machining order among all features
  std::vector<std::size_t> layers() const;
};

// Two layers belong to one feature when their filled swept regions overlap by at least this
// ratio (intersection over union).
inline constexpr double kSameFeatureOverlap = 0.5;

// Cell of the box indexes that find the features near a layer or a cut, mm.
inline constexpr double kIndexCell = 25.0;

// Exact comparisons with earlier features are bounded: a layer, a feature or a cut is compared
// exactly with at most this many of the latest earlier features near it (boxes overlapping, and
// whatever cheap test the comparison has). A real part has a handful near each; a program of
// random moves overlaps every feature with every other, and comparing all would be quadratic.
inline constexpr std::size_t kNearFeatureLimit = 16;
// Those are found among the latest this many near it by box (BoxIndex::latest): over a crowded
// area (every feature of a program of random moves spans the part) a query reads no more.
inline constexpr std::size_t kNearCandidateLimit = 128;
// A crowd: more than kCrowd earlier features near one by box. A real part has a handful near
// each feature; a crowd is a program of random strokes across the part, where every feature
// overlaps every other and each exact comparison costs as much as the feature itself. There a
// feature is compared exactly with only the latest kCrowdedFeatureLimit near it.
inline constexpr std::size_t kCrowd = 64;
inline constexpr std::size_t kCrowdedFeatureLimit = 4;
inline constexpr std::size_t near_feature_limit(std::size_t near) {
  return near > kCrowd ? kCrowdedFeatureLimit : kNearFeatureLimit;
}

// Exact comparisons charge `budget`; past it a layer starts its own group. Coarse layers make
// one group per run of one tool, one operation per layer.
std::vector<MillingGroup> group_layers(const std::vector<Layer>& layers, double finishing_allowance, WorkBudget& budget,
                                       const std::function<void()>& checkpoint = {});

}  // namespace ncbridge::feature_recognizer
