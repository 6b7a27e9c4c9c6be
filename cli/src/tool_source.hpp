#pragma once
// Where a command's tools come from: --tools (the project's tool list, a FreeCAD tool library or
// bit, a Fusion 360 tool library export) or --tool-table (a LinuxCNC tool table, in the units
// --tool-table-units gives). docs/formats/tools.md.
#include <string>
#include <vector>

#include "ncbridge/setup/tool_list.hpp"

namespace CLI {
class App;
}

namespace ncbridge::cli {

struct ToolSource {
  std::string tools;
  std::string tool_table;
  std::string tool_table_units = "mm";

  bool given() const { return !tools.empty() || !tool_table.empty(); }
  const std::string& file() const { return tool_table.empty() ? tools : tool_table; }
  // One of the two at most (UsageError), and that one a file (InputError).
  void check() const;
  setup::ToolList read() const;
};

// A LinuxCNC tool table has no kinds of tool, which planning needs: each tool whose kind is
// unknown gets the one its name (the table's comment) says, as shops write them: "center drill",
// "spot drill", "drill", "reamer", "tap", "face mill", "ball", "bull nose", "chamfer", "t-slot",
// "boring", "end mill"/"endmill"/"flat" (any case, '_' or '-' as spaces). The tools whose name
// says none are listed in `unnamed` (and stay unknown).
setup::ToolList with_kinds_from_names(const setup::ToolList& tools, std::vector<int>& unnamed);

// --tools, --tool-table, --tool-table-units; `tools_help` says what the tools are needed for.
void add_tool_source_options(CLI::App& command, ToolSource& source, const std::string& tools_help);

}  // namespace ncbridge::cli
