#pragma once
// Which tool of the shop's list does a job (docs/plan.md, "Tools").
#include <optional>

#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::process_planner {

// The largest face mill, else the largest flat end mill (nullptr when none).
const setup::Tool* face_tool(const setup::ToolList& tools);

// The largest flat end mill no wider than `max_diameter` (and at least `min_diameter`) whose
// flutes reach `reach` (a tool that gives no flute length is taken to reach).
const setup::Tool* end_mill(const setup::ToolList& tools, double max_diameter, double reach, double min_diameter = 0);
// The smallest flat end mill reaching `reach`.
const setup::Tool* smallest_end_mill(const setup::ToolList& tools, double reach);
// A flat end mill of exactly `diameter` (within 0.01 mm) reaching `reach`.
const setup::Tool* end_mill_of(const setup::ToolList& tools, double diameter, double reach);

// A twist drill of `diameter` (within 0.01 mm).
const setup::Tool* drill_of(const setup::ToolList& tools, double diameter);
// A reamer of `diameter` (within 0.01 mm).
const setup::Tool* reamer_of(const setup::ToolList& tools, double diameter);
// The drill to pre-drill a hole to be reamed: the largest drill 0.1 to 0.6 mm under size.
const setup::Tool* pre_drill(const setup::ToolList& tools, double diameter);
// The spot drill (preferred) or centre drill, the smallest.
const setup::Tool* centering_tool(const setup::ToolList& tools);
// A countersink / chamfer mill or spot drill whose point angle is `angle` (within 0.5 degrees)
// and that is wide enough.
const setup::Tool* countersink_tool(const setup::ToolList& tools, double angle, double diameter);

// The largest diameter a flat end mill of the list has (0 when none), for messages.
double largest(const setup::ToolList& tools, setup::ToolType type);

}  // namespace ncbridge::process_planner
