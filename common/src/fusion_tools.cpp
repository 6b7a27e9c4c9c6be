#include "ncbridge/setup/fusion_tools.hpp"

#include <yaml-cpp/yaml.h>

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "ncbridge/common/error.hpp"
#include "ncbridge/setup/yaml_input.hpp"

namespace ncbridge::setup {

namespace {

// Fusion's type names; the others (thread mill, form mill, dovetail mill, lollipop mill,
// tapered mill, counterbore, probe, ...) have no kind of ours.
constexpr std::array<std::pair<std::string_view, ToolType>, 14> kTypes{{
    {"flat end mill", ToolType::FlatEndMill},
    {"ball end mill", ToolType::BallEndMill},
    {"bull nose end mill", ToolType::BullNoseEndMill},
    {"face mill", ToolType::FaceMill},
    {"drill", ToolType::Drill},
    {"center drill", ToolType::CenterDrill},
    {"spot drill", ToolType::SpotDrill},
    {"reamer", ToolType::Reamer},
    {"tap right hand", ToolType::Tap},
    {"tap left hand", ToolType::Tap},
    {"boring bar", ToolType::BoringBar},
    {"slot mill", ToolType::TSlotMill},
    {"chamfer mill", ToolType::ChamferMill},
    {"countersink", ToolType::ChamferMill},
}};

ToolType type_named(const std::string& name) {
  for (const auto& [n, t] : kTypes) {
    if (n == name) return t;
  }
  return ToolType::Unknown;
}

std::optional<double> non_negative(const YAML::Node& map, const char* key, const std::string& file) {
  const std::optional<double> v = optional_number(map, key, file);
  if (v && *v < 0) throw InputError(location_of(map[key], file), std::string("'") + key + "' must not be negative");
  return v;
}

}  // namespace

ToolList parse_fusion_tool_library(std::string_view text, const std::string& file) {
  const YAML::Node root = parse_yaml_document(text, file);
  const YAML::Node data = root.IsMap() ? root["data"] : YAML::Node();
  if (!data || !data.IsSequence()) {
    throw InputError(location_of(data ? data : root, file), "a Fusion 360 tool library is a JSON object with a \"data\" list");
  }
  std::vector<Tool> tools;
  std::vector<SourceLocation> where;
  for (const YAML::Node& entry : data) {
    if (!entry.IsMap()) throw InputError(location_of(entry, file), "each tool is an object");
    const std::string type = optional_string(entry, "type", file).value_or("");
    if (type == "holder") continue;
    const YAML::Node post = entry["post-process"];
    if (!post || !post.IsMap()) throw InputError(location_of(entry, file), "tool without its \"post-process\" number");
    Tool t;
    t.number = required_int(post, "number", file);
    if (t.number < 0) throw InputError(location_of(post["number"], file), "tool number must be >= 0");
    where.push_back(location_of(post["number"], file));
    t.pocket = static_cast<int>(non_negative(post, "turret", file).value_or(0));
    if (t.pocket == 0) t.pocket = t.number;
    t.name = optional_string(entry, "description", file).value_or("");
    t.type = type_named(type);
    const std::string unit = optional_string(entry, "unit", file).value_or("millimeters");
    double to_mm = 1;
    if (unit == "inches") {
      to_mm = 25.4;
    } else if (unit != "millimeters") {
      throw InputError(location_of(entry["unit"], file), "unit '" + unit + "' is neither millimeters nor inches");
    }
    if (const YAML::Node g = entry["geometry"]; g && g.IsMap()) {
      t.diameter = non_negative(g, "DC", file).value_or(0) * to_mm;
      t.length = non_negative(g, "OAL", file).value_or(0) * to_mm;
      t.flute_length = non_negative(g, "LCF", file).value_or(0) * to_mm;
      t.corner_radius = non_negative(g, "RE", file).value_or(0) * to_mm;
      t.flutes = static_cast<int>(non_negative(g, "NOF", file).value_or(0));
      t.point_angle = non_negative(g, "SIG", file).value_or(0);
      t.thread_pitch = non_negative(g, "TP", file).value_or(0) * to_mm;
    }
    if (t.type == ToolType::BallEndMill && t.corner_radius == 0) t.corner_radius = t.diameter / 2;
    // The first preset's cutting data (Fusion's feeds are per minute in the tool's unit).
    if (const YAML::Node start = entry["start-values"]; start && start.IsMap()) {
      if (const YAML::Node presets = start["presets"]; presets && presets.IsSequence() && presets.size() > 0 &&
                                                       presets[0].IsMap()) {
        const YAML::Node preset = presets[0];
        t.spindle_rpm = non_negative(preset, "n", file).value_or(0);
        t.feed = non_negative(preset, "v_f", file).value_or(0) * to_mm;
        t.plunge_feed = non_negative(preset, "v_f_plunge", file).value_or(0) * to_mm;
      }
    }
    tools.push_back(std::move(t));
  }
  for (std::size_t i = 0; i < tools.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (tools[j].number == tools[i].number) {
        throw InputError(where[i], "tool number " + std::to_string(tools[i].number) + " appears twice");
      }
    }
  }
  return ToolList(std::move(tools));
}

}  // namespace ncbridge::setup
