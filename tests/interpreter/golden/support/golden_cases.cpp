#include "golden_cases.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ncbridge::testing {

std::vector<GoldenCase> read_golden_cases(const std::filesystem::path& golden_dir,
                                          const std::filesystem::path& shared_dir) {
  const auto file = golden_dir / "cases.txt";
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  const auto resolve = [&](const std::string& p) {
    const std::string shared_prefix = "@shared/";
    if (p.rfind(shared_prefix, 0) == 0) return shared_dir / p.substr(shared_prefix.size());
    return golden_dir / p;
  };
  std::vector<GoldenCase> cases;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    std::istringstream words(line);
    std::string name;
    if (!(words >> name) || name[0] == '#') continue;
    GoldenCase c;
    c.name = name;
    c.program = golden_dir / "programs" / (name + ".ngc");
    c.expected = golden_dir / "expected" / (name + ".canon");
    c.rs274_tool_table = golden_dir / "tools" / "metric.rs274.tbl";
    c.tools_kind = "tool-table-mm";
    c.tools_file = golden_dir / "tools" / "metric.mm.tbl";
    std::string kv;
    while (words >> kv) {
      const auto eq = kv.find('=');
      if (eq == std::string::npos) {
        throw std::runtime_error(file.string() + ":" + std::to_string(line_number) + ": expected key=value, got " + kv);
      }
      const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
      if (key == "program") c.program = resolve(value);
      else if (key == "rs274-tools") c.rs274_tool_table = resolve(value);
      else if (key == "tool-table-mm" || key == "tool-table-inch" || key == "tools-json") {
        c.tools_kind = key;
        c.tools_file = resolve(value);
      } else if (key == "subroutine-path") c.subroutine_path = resolve(value);
      else throw std::runtime_error(file.string() + ":" + std::to_string(line_number) + ": unknown key " + key);
    }
    if (c.tools_kind == "tools-json") {
      c.tool_arguments = {"--tools", c.tools_file.string()};
    } else {
      c.tool_arguments = {"--tool-table", c.tools_file.string(), "--tool-table-units",
                          c.tools_kind == "tool-table-mm" ? "mm" : "inch"};
    }
    cases.push_back(std::move(c));
  }
  return cases;
}

}  // namespace ncbridge::testing
