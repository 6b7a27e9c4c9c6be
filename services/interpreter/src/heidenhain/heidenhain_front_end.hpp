#pragma once
// HEIDENHAIN TNC conversational (iTNC 530 / TNC 640) front-end: BEGIN/END PGM, BLK FORM,
// TOOL CALL/DEF, L/LP, CC, C, CR, CT, CP (helix with IPA), RND, CHF, R0/RL/RR, F/FMAX, M,
// incremental I-words, CYCL DEF 1 (old pecking), 7 (datum shift), 10 (rotation), 200, 201,
// 203, 205, 207, 208 with CYCL CALL, CYCL CALL POS, M99 and M89, LBL / CALL LBL REP, Q
// parameters with FN 0-4, FN 9-12 jumps and Q formulas. Every block is lowered onto neutral
// RS274 blocks (lowering/dialect_machine.hpp); the meaning of keywords and cycle parameters is
// in dialects/heidenhain.yaml.
#include "lowering/program_text.hpp"
#include "ncbridge/canonical/call.hpp"
#include "ncbridge/interpreter/interpreter.hpp"

namespace ncbridge::interpreter::heidenhain {

void run(lowering::ProgramText program, const Options& options, canonical::Sink& sink);

}  // namespace ncbridge::interpreter::heidenhain
