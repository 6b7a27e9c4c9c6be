#include "tool_source.hpp"

#include <CLI/CLI.hpp>

#include "errors.hpp"
#include "input_files.hpp"

namespace ncbridge::cli {

void ToolSource::check() const {
  if (!tools.empty() && !tool_table.empty()) throw UsageError("--tool-table and --tools: give one tool list");
  if (!tools.empty()) require_input_file(tools, "--tools");
  if (!tool_table.empty()) require_input_file(tool_table, "--tool-table");
}

setup::ToolList ToolSource::read() const {
  check();
  if (!tool_table.empty()) {
    const auto units = tool_table_units == "inch" ? setup::LengthUnits::Inches : setup::LengthUnits::Millimeters;
    return setup::read_linuxcnc_tool_table(tool_table, units);
  }
  if (!tools.empty()) return setup::read_tool_list(tools);
  return {};
}

void add_tool_source_options(CLI::App& command, ToolSource& source, const std::string& tools_help) {
  command.add_option("--tools", source.tools,
                     "Tool list: ncbridge JSON/YAML, FreeCAD library (.fctl) or bit (.fctb), Fusion 360 library JSON "
                     "(docs/formats/tools.md)" + tools_help);
  command.add_option("--tool-table", source.tool_table, "LinuxCNC tool table (.tbl), instead of --tools");
  command.add_option("--tool-table-units", source.tool_table_units, "Units of the tool table values (default mm)")
      ->check(CLI::IsMember({"mm", "inch"}));
}

}  // namespace ncbridge::cli
