#include "tool_source.hpp"

#include <CLI/CLI.hpp>

#include <cctype>
#include <string_view>
#include <utility>

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

setup::ToolList with_kinds_from_names(const setup::ToolList& tools, std::vector<int>& unnamed) {
  using setup::ToolType;
  static const std::vector<std::pair<std::string_view, ToolType>> kWords{
      {"center drill", ToolType::CenterDrill}, {"centre drill", ToolType::CenterDrill}, {"spot drill", ToolType::SpotDrill},
      {"spot", ToolType::SpotDrill},           {"drill", ToolType::Drill},              {"ream", ToolType::Reamer},
      {"tap", ToolType::Tap},                  {"face", ToolType::FaceMill},            {"ball", ToolType::BallEndMill},
      {"bull", ToolType::BullNoseEndMill},     {"chamfer", ToolType::ChamferMill},      {"t slot", ToolType::TSlotMill},
      {"tslot", ToolType::TSlotMill},          {"boring", ToolType::BoringBar},         {"end mill", ToolType::FlatEndMill},
      {"endmill", ToolType::FlatEndMill},      {"flat", ToolType::FlatEndMill}};
  std::vector<setup::Tool> out = tools.tools();
  for (setup::Tool& t : out) {
    if (t.type != ToolType::Unknown) continue;
    std::string name = t.name;
    for (char& c : name) c = c == '_' || c == '-' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const auto& [word, type] : kWords) {
      if (name.find(word) != std::string::npos) {
        t.type = type;
        break;
      }
    }
    if (t.type == ToolType::Unknown) unnamed.push_back(t.number);
  }
  return setup::ToolList(std::move(out));
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
