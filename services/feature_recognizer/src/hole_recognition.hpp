#pragma once
// Phase 1, holes: every axial pass (drilling cycles, z-only feed motion) at one XY position is
// one round hole; the drilling, peck drilling, reaming, boring and tapping passes made there
// become its operations in order.
#include <vector>

#include "cutting_layers.hpp"

namespace ncbridge::feature_recognizer {

struct HoleCandidate {
  Point2 at;
  double diameter = 0;       // of the largest tool
  double z_bottom = 0;       // deepest tool tip
  double point_angle = 0;    // of the tool that went deepest, 0 = flat
  std::vector<RecognizedOperation> operations;
  std::size_t first_workingstep = 0;
  std::size_t sequence = 0;  // of its first pass
};

// Two passes closer than this in XY (mm) are at the same hole.
inline constexpr double kSameHoleDistance = 0.05;

std::vector<HoleCandidate> recognize_holes(const std::vector<DrillPass>& passes);

OperationType hole_operation_type(const setup::Tool& tool, const std::optional<canonical::CycleTag>& cycle,
                                  int passes);

}  // namespace ncbridge::feature_recognizer
