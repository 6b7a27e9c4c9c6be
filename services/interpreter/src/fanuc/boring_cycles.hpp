#pragma once
// Fanuc's fine boring (G76) and back boring (G87): cycles whose motion no RS274 cycle has (an
// oriented spindle stop and a sideways shift of the tool off the bored wall), spelled out block
// by block as the control moves, every call tagged as one hole of the cycle. G76 is tagged as
// G86 (860: boring, spindle stopped at the bottom, rapid out: ISO 14649 BORING with
// spindle_stop_at_bottom, which is what the shift protects) and G87 as 870 (BACK_BORING, r the
// R point under the part where cutting starts, z the Z point where it ends); q is the shift.
#include <cstdint>

#include "lowering/dialect_machine.hpp"

namespace ncbridge::interpreter::fanuc {

// One hole, in executor coordinates (the frame already applied).
struct BoringHole {
  double x = 0, y = 0;
  double initial = 0;       // the initial level (G98 return level)
  double r = 0;             // R point
  double z = 0;             // Z point: the bottom for G76, the top of the back bore for G87
  double shift_x = 0, shift_y = 0;  // Q in the direction parameter 5101 (RD1, RD2) selects
  double dwell = 0;         // seconds
  double q = 0;             // |Q| as written, for the tag
  int repeat = 1;
};

// G76: rapid to the hole and to R, feed to Z, dwell, oriented spindle stop, shift by Q, rapid
// out to the initial level (G98) or R (G99), shift back, spindle on again.
void fine_boring(lowering::DialectMachine& m, const BoringHole& h, std::uint32_t column);
// G87: at the initial level an oriented stop and shift, rapid down to R (under the part), shift
// back, spindle on, feed up to Z, dwell, oriented stop, shift, rapid up to the initial level,
// shift back, spindle on. Always returns to the initial level (Fanuc: no R point return).
void back_boring(lowering::DialectMachine& m, const BoringHole& h, std::uint32_t column);

}  // namespace ncbridge::interpreter::fanuc
