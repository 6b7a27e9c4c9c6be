#pragma once
// Spindle speed and feeds for a tool doing one kind of cut: the tool list's own values when it
// gives them, else the defaults of docs/plan.md (cutting speed and feed per tooth or per
// revolution for the work material, scaled with the tool's diameter).
#include "ncbridge/process_planner/planner.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::process_planner {

enum class Cut : std::uint8_t { Facing, Milling, Slotting, HoleMilling, Drilling, CenterDrilling, Reaming };

struct CuttingData {
  double rpm = 0;     // rev/min
  double feed = 0;    // mm/min
  double plunge = 0;  // mm/min
  bool from_tool_list = false;
};

CuttingData cutting_data(const setup::Tool& tool, Cut cut, const Options& options);

}  // namespace ncbridge::process_planner
