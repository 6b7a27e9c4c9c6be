#pragma once
// A tool of the tool list as the ISO 14649-111 (draft) MILLING_CUTTING_TOOL it is.
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/stepnc/resources.hpp"

namespace ncbridge::cc1_builder {

stepnc::MillingCuttingTool milling_cutting_tool(const setup::Tool& tool);

}  // namespace ncbridge::cc1_builder
