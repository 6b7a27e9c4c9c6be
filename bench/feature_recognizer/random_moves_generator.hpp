#pragma once
// A program of random moves for recognition benchmarks: no features in it, only dense cuts that
// overlap each other at random depths, to hold the recogniser's cost on input that is nothing
// like a part. Several tools (a face mill, end mills of 12, 6 and 3 mm, a spot drill, a drill);
// each tool cuts random walks (lines of 0.2 to 60 mm at random angles, arcs of 1 to 25 mm
// radius, some helical, ramps) at random depths, entered by a plunge or a ramp and left by a
// rapid; the drills drill random points with G81/G83. Deterministic; runs in LinuxCNC's rs274.
#include <cstdint>
#include <string>

#include "milling_program_generator.hpp"

namespace ncbridge::bench {

MillingProgram generate_random_moves_program(long lines, std::uint64_t seed);

}  // namespace ncbridge::bench
