#pragma once
// The process planner (part features + the shop's tool list -> ISO 14649 workingsteps): decides
// how each feature is made (facing, roughing and finishing of pockets, slots, steps and the
// outside profile, centre drilling, drilling, peck drilling, reaming, helical milling of holes
// no drill fits), picks the tools, strategies, allowances and cutting data, orders the work
// (faces, roughing, holes, finishing) and builds the CC2 project: features with their
// workingsteps, no toolpaths (the toolpath_generator makes those). The rules and defaults are in
// docs/plan.md.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/part_reader/part.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::process_planner {

// Work material: picks the default cutting data (docs/plan.md) where the tool list gives none.
enum class Material : std::uint8_t { Steel, Aluminium, StainlessSteel, CastIron, Brass, Plastic };
std::optional<Material> material_from_string(std::string_view name);
std::string_view to_string(Material material);

struct Options {
  Material material = Material::Steel;
  double side_allowance = 0.5;     // mm left on walls by roughing
  double bottom_allowance = 0.2;   // mm left on floors by roughing
  double peck_ratio = 3.0;         // holes deeper than this many diameters are peck drilled
  double ream_band = 0.04;         // mm: a hole whose diameter tolerance band is narrower is reamed
  double security_clearance = 10;  // mm: the security plane above the stock top
  double retract_clearance = 2;    // mm: operations retract this far above their feature
  double max_spindle_rpm = 12000;
  std::string project_id;          // default: the part's name
};

struct PlannedFeature {
  std::size_t part_feature = 0;     // index into Part::features
  std::size_t project_feature = 0;  // index into Plan::project.features
  std::vector<std::size_t> workingsteps;  // indices into project.main_workplan.its_elements, in order
};

struct Plan {
  stepnc::Project project;
  std::vector<PlannedFeature> features;  // the part's planned features, in the part's order
  std::vector<part_reader::Warning> warnings;
};

// Plans every accessible feature of `part` (its setup frame: z up) cut from `stock`. Throws
// ncbridge::InputError naming the feature and the tool it needs when no tool in `tools` can
// make it.
Plan plan(const part_reader::Part& part, const setup::Stock& stock, const setup::ToolList& tools, const Options& options = {});

}  // namespace ncbridge::process_planner
