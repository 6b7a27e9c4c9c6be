#pragma once
// The CC2 project from the planned operations: tools, technologies and machine functions as
// the operations need them, one MACHINING_WORKINGSTEP per operation in workplan order (faces,
// roughing, holes, finishing; within a phase by kind, then by tool so a tool does all its work
// at once, then in the part's feature order).
#include <string>
#include <vector>

#include "ncbridge/process_planner/planner.hpp"
#include "operation_plan.hpp"

namespace ncbridge::process_planner {

struct FeaturePlan {
  std::size_t part_feature = 0;
  std::string id;
  stepnc::Feature feature;
  std::vector<PlannedOperation> operations;  // in the order the feature needs them
};

void build_workplan(const std::vector<FeaturePlan>& features, const setup::Stock& stock, const part_reader::Part& part,
                    const Options& options, Plan& out);

}  // namespace ncbridge::process_planner
