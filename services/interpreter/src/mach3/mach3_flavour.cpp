// Mach3/Mach4: the Fanuc-style front-end with Mach's table and conventions.
#include "mach3/mach3_flavour.hpp"

namespace ncbridge::interpreter::mach3 {

fanuc::Flavour mach3_flavour() {
  fanuc::Flavour f;
  f.table = "mach3";
  f.macro_b = false;          // Mach3 has #parameters and [expressions] but no IF/WHILE/GOTO
  f.packed_m98_count = false; // M98 P<O-number> L<repeats>
  f.dwell_p_in_ms = false;    // G4 P and G82 P in seconds (Mach's default configuration)
  f.semicolon_comments = true; // `M06 T01 ; 0.0315` (pcb-gcode's Mach3 profile)
  return f;
}

}  // namespace ncbridge::interpreter::mach3
