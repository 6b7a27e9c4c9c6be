#pragma once
// "The same motion": two call sequences, each replayed from its own start state, make the same
// moves (moves that do not move dropped), dwells and other actions, each in the same machine
// state where the action depends on it (feed and path mode at feed moves, spindle and coolant:
// a rapid is positioning, and how a control blends it is its own business).
// The writer uses it to check that a cycle block it would write makes the hole's motion.
#include <span>

#include "machine_state.hpp"
#include "ncbridge/canonical/call.hpp"

namespace ncbridge::gcode_writer {

bool same_motion(const MachineState& start_a, std::span<const canonical::Data> a, const MachineState& start_b,
                 std::span<const canonical::Data> b, double tolerance);

}  // namespace ncbridge::gcode_writer
