#include "ncbridge/setup/tool_list.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "ncbridge/common/error.hpp"
#include "ncbridge/setup/freecad_tools.hpp"
#include "ncbridge/setup/fusion_tools.hpp"
#include "ncbridge/setup/yaml_input.hpp"

namespace ncbridge::setup {

namespace {

constexpr std::array<std::pair<std::string_view, ToolType>, 12> kToolTypeNames{{
    {"face_mill", ToolType::FaceMill},       {"flat_end_mill", ToolType::FlatEndMill},
    {"ball_end_mill", ToolType::BallEndMill}, {"bull_nose_end_mill", ToolType::BullNoseEndMill},
    {"drill", ToolType::Drill},              {"center_drill", ToolType::CenterDrill},
    {"spot_drill", ToolType::SpotDrill},     {"reamer", ToolType::Reamer},
    {"tap", ToolType::Tap},                  {"boring_bar", ToolType::BoringBar},
    {"t_slot_mill", ToolType::TSlotMill},    {"chamfer_mill", ToolType::ChamferMill},
}};

// Names other tools write for the same kinds (FreeCAD, common CAM vocabularies).
constexpr std::array<std::pair<std::string_view, ToolType>, 9> kToolTypeAliases{{
    {"twist_drill", ToolType::Drill},     {"endmill", ToolType::FlatEndMill},
    {"end_mill", ToolType::FlatEndMill},  {"ball_end", ToolType::BallEndMill},
    {"ballend", ToolType::BallEndMill},   {"bullnose", ToolType::BullNoseEndMill},
    {"centerdrill", ToolType::CenterDrill}, {"spotdrill", ToolType::SpotDrill},
    {"chamfer", ToolType::ChamferMill},
}};

// `where[i]` is where tool i's number was read (empty for a list built in code): a number
// given twice is an error at its second place.
void sort_and_check(std::vector<Tool>& tools, const std::string& file, const std::vector<SourceLocation>& where = {}) {
  std::map<int, std::size_t> first;
  for (std::size_t i = 0; i < tools.size(); ++i) {
    if (tools[i].listed == 0) tools[i].listed = static_cast<int>(i) + 1;
    if (!first.emplace(tools[i].number, i).second) {
      const SourceLocation at = i < where.size() ? where[i] : SourceLocation{file, 1, 1};
      throw InputError(at, "tool number " + std::to_string(tools[i].number) + " appears twice");
    }
  }
  std::sort(tools.begin(), tools.end(), [](const Tool& a, const Tool& b) { return a.number < b.number; });
}

}  // namespace

std::string_view to_string(ToolType type) {
  for (const auto& [name, t] : kToolTypeNames) {
    if (t == type) return name;
  }
  return "unknown";
}

std::optional<ToolType> tool_type_from_string(std::string_view name) {
  for (const auto& [n, t] : kToolTypeNames) {
    if (n == name) return t;
  }
  for (const auto& [n, t] : kToolTypeAliases) {
    if (n == name) return t;
  }
  return std::nullopt;
}

ToolList::ToolList(std::vector<Tool> tools) : tools_(std::move(tools)) {
  sort_and_check(tools_, "");
}

const Tool* ToolList::find(int number) const {
  auto it = std::lower_bound(tools_.begin(), tools_.end(), number,
                             [](const Tool& t, int n) { return t.number < n; });
  return (it != tools_.end() && it->number == number) ? &*it : nullptr;
}

ToolList parse_tool_list(std::string_view text, const std::string& file) {
  if (text.starts_with("PK\x03\x04")) {
    throw InputError({file, 1, 1}, "a zip archive (a Fusion 360 .tools file?): export the library as JSON, or unzip it");
  }
  YAML::Node root = parse_yaml_document(text, file);
  if (root.IsMap() && !root["tools"]) {
    if (root["data"] && root["data"].IsSequence()) return parse_fusion_tool_library(text, file);
    if (root["shape"] && root["parameter"]) return ToolList({parse_freecad_tool_bit(text, file, 1)});
  }
  // (A YAML::Node assigned to takes the new value into the node it refers to: `list` is made
  // once, never assigned.)
  const YAML::Node list = root.IsMap() && root["tools"] ? root["tools"] : root;
  double to_mm = 1;  // the list's "units" (lengths; feeds per minute)
  if (root.IsMap() && root["tools"]) {
    if (const auto units = optional_string(root, "units", file)) {
      if (*units == "inch" || *units == "in" || *units == "inches") {
        to_mm = 25.4;
      } else if (*units != "mm" && *units != "millimeters") {
        throw InputError(location_of(root["units"], file), "units must be mm or inch, not '" + *units + "'");
      }
    }
  }
  if (!list.IsSequence()) {
    throw InputError(location_of(root, file), "a tool list is a list of tools (or {\"tools\": [...]})");
  }
  std::vector<Tool> tools;
  std::vector<SourceLocation> where;
  for (const YAML::Node& node : list) {
    if (!node.IsMap()) throw InputError(location_of(node, file), "each tool is an object");
    if (node["number"]) where.push_back(location_of(node["number"], file));
    Tool t;
    t.number = required_int(node, "number", file);
    if (t.number < 0) throw InputError(location_of(node["number"], file), "tool number must be >= 0");
    t.name = optional_string(node, "name", file).value_or("");
    if (auto type = optional_string(node, "type", file)) {
      auto parsed = tool_type_from_string(*type);
      if (!parsed) {
        std::string known;
        for (const auto& [n, _] : kToolTypeNames) known += (known.empty() ? "" : ", ") + std::string(n);
        throw InputError(location_of(node["type"], file), "unknown tool type '" + *type + "' (known: " + known + ")");
      }
      t.type = *parsed;
    }
    t.diameter = optional_number(node, "diameter", file).value_or(0);
    t.length = optional_number(node, "length", file).value_or(0);
    t.corner_radius = optional_number(node, "corner_radius", file).value_or(0);
    t.flute_length = optional_number(node, "flute_length", file).value_or(0);
    t.flutes = static_cast<int>(optional_number(node, "flutes", file).value_or(0));
    t.point_angle = optional_number(node, "point_angle", file)
                        .value_or(optional_number(node, "tip_angle", file).value_or(0));
    t.thread_pitch = optional_number(node, "thread_pitch", file).value_or(0);
    t.pocket = static_cast<int>(optional_number(node, "pocket", file).value_or(t.number));
    t.spindle_rpm = optional_number(node, "rpm", file).value_or(optional_number(node, "spindle_rpm", file).value_or(0));
    t.feed = optional_number(node, "feed", file).value_or(0);
    t.plunge_feed = optional_number(node, "plunge", file).value_or(optional_number(node, "plunge_feed", file).value_or(0));
    for (const char* key : {"diameter", "length", "corner_radius", "flute_length", "rpm", "spindle_rpm", "feed", "plunge", "plunge_feed"}) {
      if (optional_number(node, key, file).value_or(0) < 0) {  // (a key without a value is null, not a number)
        throw InputError(location_of(node[key], file), std::string(key) + " must not be negative");
      }
    }
    for (double* length : {&t.diameter, &t.length, &t.corner_radius, &t.flute_length, &t.thread_pitch, &t.feed, &t.plunge_feed}) {
      *length *= to_mm;
    }
    tools.push_back(std::move(t));
  }
  sort_and_check(tools, file, where);
  return ToolList(std::move(tools));
}

ToolList read_tool_list(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".fctl") return read_freecad_tool_library(file);
  if (extension == ".fctb") return read_freecad_tool_bit(file);
  if (extension == ".tbl") {
    throw InputError({file.string(), 0, 0}, "a LinuxCNC tool table: give it with --tool-table (and --tool-table-units)");
  }
  return parse_tool_list(read_text_file(file), file.string());
}

// LinuxCNC tool table: each line `T<n> P<pocket> [X..] [Y..] [Z..] [A..]... [D<diam>] [I..] [J..] [Q..] [;comment]`.
ToolList parse_linuxcnc_tool_table(std::string_view text, LengthUnits units, const std::string& file) {
  const double to_mm = units == LengthUnits::Inches ? 25.4 : 1.0;
  std::vector<Tool> tools;
  std::vector<SourceLocation> where;
  std::uint32_t line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view line = text.substr(pos, eol - pos);
    pos = eol + 1;
    ++line_no;
    std::string comment;
    if (auto semi = line.find(';'); semi != std::string_view::npos) {
      comment = std::string(line.substr(semi + 1));
      line = line.substr(0, semi);
    }
    Tool t;
    bool has_t = false;
    SourceLocation t_at{file, line_no, 1};
    std::size_t i = 0;
    while (i < line.size()) {
      char c = line[i];
      if (c == ' ' || c == '\t' || c == '\r') { ++i; continue; }
      const std::uint32_t column = static_cast<std::uint32_t>(i + 1);
      char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      ++i;
      std::size_t start = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
      std::string_view num = line.substr(start, i - start);
      if (!num.empty() && num.front() == '+') num.remove_prefix(1);
      double value = 0;
      auto [p, ec] = std::from_chars(num.data(), num.data() + num.size(), value);
      if (num.empty() || ec != std::errc() || p != num.data() + num.size()) {
        throw InputError({file, line_no, column}, std::string("bad number after '") + letter + "' in tool table");
      }
      switch (letter) {
        case 'T': t.number = static_cast<int>(value); has_t = true; t_at.column = column; break;
        case 'P': t.pocket = static_cast<int>(value); break;
        case 'D': t.diameter = value * to_mm; break;
        case 'Z': t.length = value * to_mm; break;
        case 'X': t.x_offset = value * to_mm; break;
        case 'Y': case 'A': case 'B': case 'C': case 'U': case 'V': case 'W':
        case 'I': case 'J': case 'Q': break;  // kept by LinuxCNC; no meaning for 3-axis milling here
        default:
          throw InputError({file, line_no, column}, std::string("unknown word '") + letter + "' in tool table");
      }
    }
    if (!has_t) {
      if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;  // blank or comment-only
      throw InputError({file, line_no, 1}, "tool table line without a T word");
    }
    auto first = comment.find_first_not_of(' ');
    t.name = first == std::string::npos ? std::string() : comment.substr(first);
    if (t.pocket == 0) t.pocket = t.number;
    tools.push_back(std::move(t));
    where.push_back(t_at);
  }
  sort_and_check(tools, file, where);
  return ToolList(std::move(tools));
}

ToolList read_linuxcnc_tool_table(const std::filesystem::path& file, LengthUnits units) {
  return parse_linuxcnc_tool_table(read_text_file(file), units, file.string());
}

}  // namespace ncbridge::setup
