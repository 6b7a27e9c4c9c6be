// generate_milling_program LINES DIR: writes DIR/part.ngc, DIR/tools.json, DIR/stock.json (a
// realistic 2.5D program of about LINES lines, milling_program_generator.hpp) and prints the
// number of pockets.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "milling_program_generator.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: generate_milling_program LINES DIR\n");
    return 2;
  }
  const long lines = std::strtol(argv[1], nullptr, 10);
  const std::filesystem::path dir = argv[2];
  std::filesystem::create_directories(dir);
  const auto p = ncbridge::bench::generate_milling_program(lines);
  std::ofstream(dir / "part.ngc", std::ios::binary) << p.program;
  std::ofstream(dir / "tools.json", std::ios::binary) << p.tools;
  std::ofstream(dir / "stock.json", std::ios::binary) << p.stock;
  std::printf("%d pockets, %d holes\n", p.cells, 2 * p.cells);
  return 0;
}
