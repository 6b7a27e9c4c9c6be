#pragma once
// One milling workingstep (a TWO5D_MILLING_OPERATION on a feature) into cutter-location moves.
#include <string>
#include <vector>

#include "motion.hpp"
#include "ncbridge/stepnc/project.hpp"
#include "part_model.hpp"

namespace ncbridge::toolpath_generator {

struct MillingInput {
  const ShapedFeature* feature = nullptr;
  const stepnc::Feature* cc2_feature = nullptr;
  const stepnc::Operation* operation = nullptr;
  const stepnc::MillingCuttingTool* tool = nullptr;
  const stepnc::MillingTechnology* technology = nullptr;
  std::string workingstep;  // for messages
  double safe_z = 0;
};

struct MillingOutput {
  Motion3 motion;
  double lowest_z = 0;
};

// Generates the moves and records what they cut in `part`. Throws InputError for what cannot be
// generated; notes choices in `warnings`.
MillingOutput mill(PartModel& part, const MillingInput& in, const Options& options, std::vector<std::string>& warnings);

}  // namespace ncbridge::toolpath_generator
