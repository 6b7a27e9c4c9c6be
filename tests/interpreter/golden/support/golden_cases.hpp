#pragma once
// The golden cases listed in tests/interpreter/golden/cases.txt (format described there).
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace ncbridge::testing {

struct GoldenCase {
  std::string name;
  std::filesystem::path program;
  std::filesystem::path expected;         // expected/NAME.canon
  std::filesystem::path rs274_tool_table; // inches
  std::vector<std::string> tool_arguments;  // ncbridge options naming the same tools
  std::filesystem::path tools_file;       // the file in tool_arguments
  std::string tools_kind;                 // "tool-table-mm", "tool-table-inch" or "tools-json"
  std::filesystem::path subroutine_path;  // empty when none
};

inline void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name; }

// Reads `golden_dir`/cases.txt; `shared_dir` replaces a leading "@shared/". Throws
// std::runtime_error naming the line on a malformed entry.
std::vector<GoldenCase> read_golden_cases(const std::filesystem::path& golden_dir,
                                          const std::filesystem::path& shared_dir);

}  // namespace ncbridge::testing
