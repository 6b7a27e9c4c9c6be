#pragma once
// A realistic 2.5D milling program of any length for recognition benchmarks: a grid of cells on
// one block, the top faced bidirectionally, then in every cell a rectangular pocket roughed in
// contour-parallel layers, and two drilled holes (G81). Deterministic; runs in LinuxCNC's rs274.
#include <string>

namespace ncbridge::bench {

struct MillingProgram {
  std::string program;  // RS274/NGC text, about `lines` lines
  std::string tools;    // tools.json (docs/formats/tools.md)
  std::string stock;    // stock.json (docs/formats/stock.md)
  int cells = 0;        // pockets (and hole pairs) in the program
};

MillingProgram generate_milling_program(long lines);

}  // namespace ncbridge::bench
