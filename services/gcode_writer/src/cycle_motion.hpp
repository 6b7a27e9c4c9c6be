#pragma once
// The calls the interpreter's executor makes for one canned-cycle block of one hole (G73, G74,
// G81-G89 in absolute mode; services/interpreter/src/canned_cycles.cpp, after LinuxCNC), from
// the state the reader is in: what a cycle block the writer writes will make the reader do.
#include <vector>

#include "machine_state.hpp"
#include "ncbridge/canonical/call.hpp"

namespace ncbridge::gcode_writer {

// The reader's canned-cycle state besides the machine state.
struct CycleReader {
  int motion = 800;            // the motion mode, G code x 10 (800: G80, none)
  bool initial_valid = false;  // the G98 level is set (by the first hole after another motion)
  double initial_level = 0;
  bool retract_to_r = true;    // G99 (the executor starts in R-plane retract)
  // sticky words of the running cycle, as written
  double r = 0, z = 0, q = 0, p = 0;
};

// One cycle block: the cycle (G code x 10), the hole in the plane's first and second axes,
// and the words (absolute), R plane, bottom, Q peck, P dwell, I J K (G87).
struct CycleBlock {
  int motion = 810;
  double a = 0, b = 0;
  double r = 0, z = 0, q = 0, p = 0, i = 0, j = 0, k = 0;
};

// The calls, applied to `state`; `cycle` is updated as the reader updates it.
std::vector<canonical::Data> simulate_cycle(MachineState& state, CycleReader& cycle, const CycleBlock& block);

// A move of the reader that is not a cycle ends the G98 level (LinuxCNC).
inline void note_other_motion(CycleReader& cycle, int motion) {
  cycle.motion = motion;
  cycle.initial_valid = false;
}

}  // namespace ncbridge::gcode_writer
