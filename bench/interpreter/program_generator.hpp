#pragma once
// A long, deterministic 3-axis RS274/NGC milling program for benchmarks: rapid and feed moves,
// G2/G3 arcs (I J and R forms), comments, N numbers, numbered and named parameters, expressions.
// LinuxCNC's rs274 runs it too, so both interpreters can be timed on the same file.
#include <cstdint>
#include <string>

namespace ncbridge::bench {

// Exactly `lines` lines (at least 16), the same text for the same seed on every platform.
std::string generate_ngc_program(long lines, std::uint64_t seed);

}  // namespace ncbridge::bench
