// Writes the benchmark program (see program_generator.hpp) to standard output.
//   generate_ngc_program [LINES] [SEED] > program.ngc      (defaults: 1000000 lines, seed 1)
#include <cstdio>
#include <cstdlib>

#include "program_generator.hpp"

int main(int argc, char** argv) {
  const long lines = argc > 1 ? std::atol(argv[1]) : 1000000;
  const auto seed = static_cast<std::uint64_t>(argc > 2 ? std::atoll(argv[2]) : 1);
  if (lines < 16) {
    std::fprintf(stderr, "usage: generate_ngc_program [LINES >= 16] [SEED]\n");
    return 2;
  }
  const std::string program = ncbridge::bench::generate_ngc_program(lines, seed);
  return std::fwrite(program.data(), 1, program.size(), stdout) == program.size() ? 0 : 1;
}
