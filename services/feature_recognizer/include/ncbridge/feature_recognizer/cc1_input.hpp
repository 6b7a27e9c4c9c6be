#pragma once
// Adapter from the CC1 model (cc1_builder's stepnc::Project) to the recogniser's input.
// Coordinates are taken as they are in the model (the program frame); freeform operations'
// cutter-location trajectories become moves (CONNECT trajectories and rapid movements as
// rapids, XY arcs as arcs, other curves as lines), and drilling-family operations on ROUND_HOLEs
// become one axial pass from the retract plane to the hole bottom, tagged with the cycle.
#include <optional>
#include <vector>

#include "ncbridge/feature_recognizer/toolpath.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::feature_recognizer {

// One ToolpathWorkingstep per MACHINING_WORKINGSTEP, in workplan order (so the recogniser's
// workingstep indices are the CC1 workingsteps' positions among the machining workingsteps).
// A tool without a T number (its id is not "T<n> ...") gets 10001 + its index in the project.
std::vector<ToolpathWorkingstep> workingsteps_from_cc1(const stepnc::Project& cc1);

// The rawpiece's bounding block, when the model has one.
std::optional<setup::Stock> stock_from_cc1(const stepnc::Project& cc1);

}  // namespace ncbridge::feature_recognizer
