#pragma once
// An arc of several turns (ARC_FEED with |rotation| > 1) as one arc per turn: the full turns
// first, each back at the start point, then the last (partial) arc to the end, the helix rising
// evenly along the swept angle. For dialects whose arcs turn at most once (Fanuc, Mach3).
#include <vector>

#include "ncbridge/canonical/call.hpp"

namespace ncbridge::gcode_writer {

// Refuses nothing: an arc that also moves a, b, c, u, v or w keeps them for its last piece.
std::vector<canonical::ArcFeed> split_turns(const canonical::Pose& start, const canonical::ArcFeed& arc,
                                            canonical::Plane plane);

}  // namespace ncbridge::gcode_writer
