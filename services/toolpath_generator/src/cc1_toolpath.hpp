#pragma once
// Generated moves as ISO 14649 cutter-location trajectories (docs/cc1.md, "Toolpaths"): feeds
// as TRAJECTORY_PATHs (entries with their own, slower technology), rapids as CONNECTs; lines
// as POLYLINEs, arcs in XY as TRIMMED_CURVEs on CIRCLEs of at most half a turn, helices as
// POLYLINEs within 0.001 mm.
#include <optional>

#include "motion.hpp"
#include "ncbridge/stepnc/operations.hpp"

namespace ncbridge::toolpath_generator {

stepnc::ToolpathList toolpath_list(const Motion3& motion, std::optional<stepnc::TechnologyRef> entry_technology);

// A polyline of rapid moves through the given points (a RAPID_MOVEMENT's toolpath).
stepnc::ToolpathList rapid_list(const std::vector<Point3>& points);

}  // namespace ncbridge::toolpath_generator
