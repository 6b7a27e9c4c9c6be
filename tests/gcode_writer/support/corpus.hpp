#pragma once
// The programs every writer test runs over: the interpreter's golden programs, its dialect test
// programs (hand-written parts in five dialects and single constructs), the CAM corpus in every
// post, the paper's programs and examples/plate: each with its dialect and the tools it runs with.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "ncbridge/interpreter/interpreter.hpp"

namespace ncbridge::testing {

struct CorpusProgram {
  std::string name;                        // "golden/arc_xy_ijk", "cam/p01_block_reference/part.fanuc.nc"
  std::filesystem::path program;
  interpreter::Dialect dialect = interpreter::Dialect::Rs274Ngc;
  std::filesystem::path tools;             // the tool list or table the program runs with
  std::string tools_kind;                  // "tool-table-mm", "tool-table-inch" or "tools-json"
  std::filesystem::path rs274_tool_table;  // the same tools for LinuxCNC's rs274 (inches)
  std::vector<std::filesystem::path> subroutine_path;
  bool feed_per_second = false;            // FreeCAD's Heidenhain post writes F in mm/s
};

inline void PrintTo(const CorpusProgram& p, std::ostream* os) { *os << p.name; }

std::vector<CorpusProgram> corpus_programs();

// The interpreter options that read the program as the corpus means it (tools, dialect, ...).
interpreter::Options reading_options(const CorpusProgram& program);

// A name gtest accepts (letters, digits, _).
std::string test_name(std::string_view text);

}  // namespace ncbridge::testing
