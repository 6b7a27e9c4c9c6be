#pragma once
// The operations each kind of feature gets (docs/plan.md, "Operations"): one function per kind,
// each giving the operations in the order they are done, with their phase in the workplan.
#include <string>
#include <vector>

#include "cutting_data.hpp"
#include "ncbridge/part_reader/part.hpp"
#include "ncbridge/process_planner/planner.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/stepnc/operations.hpp"

namespace ncbridge::process_planner {

// Faces first, then roughing, then holes, then finishing.
enum class Phase : std::uint8_t { Facing, Roughing, Holes, Finishing };

struct PlannedOperation {
  Phase phase = Phase::Roughing;
  int rank = 0;                 // order of kinds within a phase (centre drilling before drilling...)
  const setup::Tool* tool = nullptr;
  Cut cut = Cut::Milling;
  std::string word;             // "ROUGH", "FINISH", "DRILL", ... (the operation's id starts with it)
  stepnc::Operation operation;  // without id, tool, technology and machine functions
};

// What every planner function needs.
struct PlanContext {
  const setup::ToolList& tools;
  const setup::Stock& stock;
  const Options& options;
  const part_reader::Part& part;
  std::vector<part_reader::Warning>& warnings;
};

// `id` names the feature in messages ("HOLE2 D=7.3MM").
std::vector<PlannedOperation> plan_face(const part_reader::Feature& f, const std::string& id, const PlanContext& c);
std::vector<PlannedOperation> plan_pocket(const part_reader::Feature& f, const std::string& id, const PlanContext& c);
std::vector<PlannedOperation> plan_slot(const part_reader::Feature& f, const std::string& id, const PlanContext& c);
std::vector<PlannedOperation> plan_step(const part_reader::Feature& f, const std::string& id, const PlanContext& c);
std::vector<PlannedOperation> plan_outside_profile(const part_reader::Feature& f, const std::string& id, const PlanContext& c);
// `counterbore`: the outer hole of a counterbore (milled flat, not drilled).
std::vector<PlannedOperation> plan_hole(const part_reader::Feature& f, const std::string& id, bool counterbore, const PlanContext& c);
// The cone of a countersunk hole: sunk with a countersink (or chamfer mill, or spot drill) of its angle.
std::vector<PlannedOperation> plan_countersink(const part_reader::Feature& f, const std::string& id, const PlanContext& c);

// The deepest cut per layer a tool may take: a fraction of its diameter, not beyond its flutes.
double axial_limit(const setup::Tool& tool, double fraction_of_diameter);

// "HOLE2 D=7.3MM (faces 12, 13)": the feature as messages name it.
std::string feature_text(const part_reader::Feature& f, const std::string& id);

}  // namespace ncbridge::process_planner
