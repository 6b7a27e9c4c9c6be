// generate_recognition_program FAMILY LINES DIR [SEED]: writes DIR/part.ngc, DIR/tools.json and
// DIR/stock.json, a program of about LINES lines of one family, and prints its size:
//   milling      a faced block with a grid of contour-parallel pockets and G81 holes
//                (milling_program_generator.hpp)
//   interpreter  the interpreter benchmark's program (bench/interpreter: random long moves of a
//                6 mm end mill at random depths across a 220 x 180 block, arcs, parameters)
//   random       random walks of several tools at random depths, drilling at random points
//                (random_moves_generator.hpp)
//   adaptive     pockets roughed by trochoidal adaptive clearing and finished with a smaller
//                tool (adaptive_program_generator.hpp)
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "adaptive_program_generator.hpp"
#include "milling_program_generator.hpp"
#include "program_generator.hpp"
#include "random_moves_generator.hpp"

int main(int argc, char** argv) {
  namespace b = ncbridge::bench;
  if (argc < 4 || argc > 5) {
    std::fprintf(stderr, "usage: generate_recognition_program milling|interpreter|random|adaptive LINES DIR [SEED]\n");
    return 2;
  }
  const std::string family = argv[1];
  const long lines = std::strtol(argv[2], nullptr, 10);
  const std::filesystem::path dir = argv[3];
  const auto seed = static_cast<std::uint64_t>(argc == 5 ? std::strtoull(argv[4], nullptr, 10) : 1);
  if (lines < 16) {
    std::fprintf(stderr, "LINES must be at least 16\n");
    return 2;
  }
  b::MillingProgram p;
  if (family == "milling") {
    p = b::generate_milling_program(lines);
  } else if (family == "interpreter") {
    p.program = b::generate_ngc_program(lines, seed);
    p.tools = "[{\"number\":1,\"name\":\"ENDMILL_6MM\",\"type\":\"flat_end_mill\",\"diameter\":6,\"length\":40}]\n";
    p.stock = "{\"units\":\"mm\",\"shape\":\"block\",\"min\":[-20,-20,-30],\"max\":[200,160,0]}\n";
  } else if (family == "random") {
    p = b::generate_random_moves_program(lines, seed);
  } else if (family == "adaptive") {
    p = b::generate_adaptive_program(lines, seed);
  } else {
    std::fprintf(stderr, "unknown family '%s'\n", family.c_str());
    return 2;
  }
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "part.ngc", std::ios::binary) << p.program;
  std::ofstream(dir / "tools.json", std::ios::binary) << p.tools;
  std::ofstream(dir / "stock.json", std::ios::binary) << p.stock;
  long count = 0;
  for (char c : p.program) count += c == '\n';
  std::printf("%s %ld lines %d cells\n", family.c_str(), count, p.cells);
  return 0;
}
