#pragma once
// SIEMENS SINUMERIK 840D front-end: G70/G71/G700/G710, G90/G91 with AC()/IC(), G17-G19, G2/G3
// with I/J/K, CR=, AR=, CIP with I1/J1/K1, CT; G54-G57, G500, TRANS/ATRANS/ROT/AROT, SUPA;
// T="name" M6 and T1 D1; R parameters with arithmetic, DEF variables, labels with
// GOTOF/GOTOB/GOTO and IF; L-subprogram and named subprogram calls (P repeats, M17/RET);
// CYCLE81-CYCLE89 called once or modally with MCALL; MSG(). POCKET/SLOT/LONGHOLE/HOLES cycles
// are recognised and reported as unsupported. The G-code dictionary and the cycles' parameter
// lists are in dialects/siemens840d.yaml.
#include "lowering/program_text.hpp"
#include "ncbridge/canonical/call.hpp"
#include "ncbridge/interpreter/interpreter.hpp"

namespace ncbridge::interpreter::siemens840d {

void run(lowering::ProgramText program, const Options& options, canonical::Sink& sink);

}  // namespace ncbridge::interpreter::siemens840d
