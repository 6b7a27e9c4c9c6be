#pragma once
// A long adaptive-clearing program for recognition benchmarks: a grid of closed rectangular
// pockets (each of its own size, 70-90 x 40-55 mm, corner radius 4, 8 deep), each roughed with
// a 10 mm end mill by trochoidal slots (two arcs per loop, 0.6-1.0 mm advance) in four 2 mm
// levels entered by a helix, the slots joined by lifts as adaptive clearing links them, then
// finished at full depth with a 6 mm end mill (the corners the 10 mm tool cannot reach: rest
// machining). Thousands of short arcs per level; every pocket's toolpath differs from the
// others'. Deterministic; runs in LinuxCNC's rs274.
#include <cstdint>
#include <string>

#include "milling_program_generator.hpp"

namespace ncbridge::bench {

MillingProgram generate_adaptive_program(long lines, std::uint64_t seed);

}  // namespace ncbridge::bench
