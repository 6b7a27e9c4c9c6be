#pragma once
// One hole of a canned cycle (the calls sharing a CycleTag::cycle_id) -> a drilling-family
// operation on a ROUND_HOLE at the hole position: docs/cc1.md, "Canned cycles".
#include <optional>
#include <string>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/stepnc/features.hpp"
#include "ncbridge/stepnc/operations.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::cc1_builder {

// The cycle's parameters in the setup frame (mm), and what its calls showed.
struct HoleCycle {
  std::uint16_t g_code_x10 = 0;
  int first_axis = 0, second_axis = 1, normal_axis = 2;
  double first = 0, second = 0;      // hole position in the plane
  double r = 0, bottom = 0;          // along the normal
  double q = 0, p = 0;               // peck increment (mm), dwell (s)
  std::optional<double> first_peck_bottom;   // end of the first feed into the hole
  std::optional<double> first_peck_retract;  // where the tool went back to after it
  bool after_first_peck = false;
  stepnc::ToolRef tool;
  stepnc::TechnologyRef technology;
  stepnc::MachineFunctionsRef machine_functions;
  stepnc::SourceLines source;

  // Notes a move of the cycle along the hole axis (for the peck retract distance).
  void observe(bool feed, double normal_from, double normal_to);
};

struct HoleResult {
  stepnc::RoundHole feature;
  stepnc::Operation operation;
};

// `number` (1, 2, ...) names the feature and operation; `tool` is the loaded tool's entry.
HoleResult make_hole(const HoleCycle& cycle, const setup::Tool& tool,
                     const std::optional<setup::Stock>& stock, double diameter_tolerance, int number);

}  // namespace ncbridge::cc1_builder
