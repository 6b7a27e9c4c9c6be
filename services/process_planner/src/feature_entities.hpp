#pragma once
// Part features as ISO 14649 CC2 features, with the placements and attributes docs/cc2.md fixes
// for CC2 (so a CC2 file from a part reads like one from a program): PLANAR_FACE at the corner
// where its passes start, ROUND_HOLE at its axis' top, CLOSED_/OPEN_POCKET and
// GENERAL_OUTSIDE_PROFILE at their outline's centre, SLOT at the start of its centre line, STEP
// at one end of its open edge.
#include <string>
#include <vector>

#include "ncbridge/part_reader/part.hpp"
#include "ncbridge/stepnc/features.hpp"

namespace ncbridge::process_planner {

// "PLANAR FACE1", "HOLE1 D=10MM", "POCKET1", "OPEN POCKET1", "SLOT1", "STEP1", "PROFILE1".
std::vector<std::string> feature_ids(const std::vector<const part_reader::Feature*>& features);

stepnc::Feature to_stepnc(const part_reader::Feature& f, const std::string& id);

// The closed outline of `f` as a composite curve (lines and arcs) in the feature's frame.
stepnc::CompositeCurve outline_curve(const std::vector<part_reader::OutlineVertex>& outline);

}  // namespace ncbridge::process_planner
