#pragma once
// Fanuc (0i/18i/30i milling) front-end, and Mach3/Mach4, which reads the same word-address
// syntax with fewer features: O/N numbers, modal G groups, G15/G16 polar coordinates, G68/G69
// rotation, G52 local coordinates, canned cycles with Fanuc's R/Q/P/K(L) words, M98/M99
// subprograms, G65 macro calls and custom macro B (#variables, arithmetic, IF/GOTO, WHILE/DO/END).
// What differs between the two is data: the dialect table (fanuc.yaml / mach3.yaml) and the
// Flavour switches below.
#include "lowering/program_text.hpp"
#include "ncbridge/canonical/call.hpp"
#include "ncbridge/interpreter/interpreter.hpp"

namespace ncbridge::interpreter::fanuc {

struct Flavour {
  const char* table = "fanuc";   // dialects/<table>.yaml
  bool macro_b = true;           // custom macro B statements (IF, WHILE, GOTO, G65)
  bool packed_m98_count = true;  // M98 P30100 = call O0100 three times (Fanuc); Mach: P is the O-number
  bool dwell_p_in_ms = true;     // G4 P and cycle P in milliseconds (Fanuc); Mach: seconds
  bool semicolon_comments = false;  // `;` starts a comment to the end of the line (Mach); Fanuc: end of block
};

Flavour fanuc_flavour();

void run(lowering::ProgramText program, const Options& options, canonical::Sink& sink, const Flavour& flavour);

}  // namespace ncbridge::interpreter::fanuc
