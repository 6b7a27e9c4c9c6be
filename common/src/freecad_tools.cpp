#include "ncbridge/setup/freecad_tools.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "ncbridge/common/error.hpp"
#include "ncbridge/setup/yaml_input.hpp"

namespace ncbridge::setup {

namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The shape file's stem, as FreeCAD's shipped shapes name the kinds.
constexpr std::array<std::pair<std::string_view, ToolType>, 9> kShapes{{
    {"endmill", ToolType::FlatEndMill}, {"ballend", ToolType::BallEndMill}, {"bullnose", ToolType::BullNoseEndMill},
    {"drill", ToolType::Drill},         {"chamfer", ToolType::ChamferMill}, {"v-bit", ToolType::ChamferMill},
    {"vbit", ToolType::ChamferMill},    {"tap", ToolType::Tap},             {"reamer", ToolType::Reamer},
}};

ToolType type_of_shape(const std::string& shape) {
  const std::string stem = lower(std::filesystem::path(shape).stem().string());
  for (const auto& [name, type] : kShapes) {
    if (stem == name) return type;
  }
  return ToolType::Unknown;
}

enum class Dimension { Length, Angle, Count };

// A FreeCAD quantity ("6.0000 mm", "0.375 \"", "118.00 °", "3") in mm, degrees or a count.
std::optional<double> quantity(const YAML::Node& parameters, const char* key, Dimension dimension, const std::string& file) {
  const YAML::Node n = parameters[key];
  if (!n || n.IsNull()) return std::nullopt;
  if (!n.IsScalar()) throw InputError(location_of(n, file), std::string("'") + key + "' must be a quantity such as \"6 mm\"");
  const std::string& text = n.Scalar();
  std::size_t start = text.find_first_not_of(' ');
  if (start == std::string::npos) start = text.size();
  double value = 0;
  const char* first = text.data() + start;
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  const auto [end, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || !std::isfinite(value)) {
    throw InputError(location_of(n, file), std::string("'") + key + "' must be a quantity such as \"6 mm\", not \"" + text + "\"");
  }
  std::string unit(end, last);
  unit.erase(0, unit.find_first_not_of(' '));
  unit.erase(unit.find_last_not_of(' ') + 1);
  unit = lower(unit);
  double scale = 0;
  switch (dimension) {
    case Dimension::Length:
      if (unit.empty() || unit == "mm") scale = 1;  // FreeCAD's own unit for lengths
      else if (unit == "cm") scale = 10;
      else if (unit == "m") scale = 1000;
      else if (unit == "um" || unit == "\xC2\xB5m") scale = 0.001;
      else if (unit == "in" || unit == "\"" || unit == "inch") scale = 25.4;
      else if (unit == "ft" || unit == "'") scale = 304.8;
      else if (unit == "thou" || unit == "mil") scale = 0.0254;
      break;
    case Dimension::Angle:
      if (unit.empty() || unit == "\xC2\xB0" || unit == "deg") scale = 1;
      else if (unit == "rad") scale = 180.0 / 3.14159265358979323846;
      break;
    case Dimension::Count:
      if (unit.empty()) scale = 1;
      break;
  }
  if (scale == 0) {
    throw InputError(location_of(n, file), std::string("'") + key + "': unit '" + unit + "' is not a " +
                                               (dimension == Dimension::Length ? "length" : dimension == Dimension::Angle ? "angle" : "count"));
  }
  if (value < 0) throw InputError(location_of(n, file), std::string("'") + key + "' must not be negative");
  return value * scale;
}

YAML::Node json_object(std::string_view text, const std::string& file, const char* what) {
  YAML::Node root = parse_yaml_document(text, file);
  if (!root.IsMap()) throw InputError(location_of(root, file), std::string("a FreeCAD ") + what + " is a JSON object");
  return root;
}

}  // namespace

Tool parse_freecad_tool_bit(std::string_view text, const std::string& file, int number) {
  const YAML::Node root = json_object(text, file, "tool bit (.fctb)");
  const YAML::Node parameters = root["parameter"];
  if (!parameters || !parameters.IsMap()) {
    throw InputError(location_of(parameters ? parameters : root, file), "a FreeCAD tool bit needs its \"parameter\" object");
  }
  Tool t;
  t.number = number;
  t.pocket = number;
  t.name = optional_string(root, "name", file).value_or("");
  const std::optional<std::string> shape = optional_string(root, "shape", file);
  if (!shape) throw InputError(location_of(root, file), "a FreeCAD tool bit needs its \"shape\"");
  t.type = type_of_shape(*shape);
  t.diameter = quantity(parameters, "Diameter", Dimension::Length, file).value_or(0);
  t.length = quantity(parameters, "Length", Dimension::Length, file).value_or(0);
  t.flute_length = quantity(parameters, "CuttingEdgeHeight", Dimension::Length, file)
                       .value_or(quantity(parameters, "CuttingEdgeLength", Dimension::Length, file).value_or(0));
  t.flutes = static_cast<int>(quantity(parameters, "Flutes", Dimension::Count, file).value_or(0));
  t.point_angle = quantity(parameters, "TipAngle", Dimension::Angle, file).value_or(0);
  if (t.type == ToolType::BallEndMill) t.corner_radius = t.diameter / 2;
  if (t.type == ToolType::BullNoseEndMill) {
    // FreeCAD's bull nose gives the radius of its flat bottom; newer bits the corner radius.
    if (auto corner = quantity(parameters, "CornerRadius", Dimension::Length, file)) {
      t.corner_radius = *corner;
    } else if (auto flat = quantity(parameters, "FlatRadius", Dimension::Length, file)) {
      if (*flat > t.diameter / 2) {
        throw InputError(location_of(parameters["FlatRadius"], file), "FlatRadius is larger than half the Diameter");
      }
      t.corner_radius = t.diameter / 2 - *flat;
    }
  }
  if (t.type == ToolType::Tap) {
    t.thread_pitch = quantity(parameters, "Pitch", Dimension::Length, file).value_or(0);
    if (t.thread_pitch == 0) {
      if (auto tpi = quantity(parameters, "TPI", Dimension::Count, file); tpi && *tpi > 0) t.thread_pitch = 25.4 / *tpi;
    }
  }
  return t;
}

ToolList read_freecad_tool_bit(const std::filesystem::path& file) {
  return ToolList({parse_freecad_tool_bit(read_text_file(file), file.string(), 1)});
}

ToolList read_freecad_tool_library(const std::filesystem::path& file) {
  const std::string name = file.string();
  const YAML::Node root = json_object(read_text_file(file), name, "tool library (.fctl)");
  const YAML::Node entries = root["tools"];
  if (!entries || !entries.IsSequence()) {
    throw InputError(location_of(entries ? entries : root, name), "a FreeCAD tool library needs its \"tools\" list");
  }
  const std::filesystem::path folder = file.parent_path();
  std::vector<Tool> tools;
  std::vector<SourceLocation> where;
  for (const YAML::Node& entry : entries) {
    if (!entry.IsMap()) throw InputError(location_of(entry, name), "each library entry is an object {\"nr\": N, \"path\": BIT}");
    const int number = required_int(entry, "nr", name);
    if (number < 0) throw InputError(location_of(entry["nr"], name), "tool number must be >= 0");
    const std::optional<std::string> path = optional_string(entry, "path", name);
    if (!path) throw InputError(location_of(entry, name), "missing 'path' (the tool bit file)");
    std::vector<std::filesystem::path> candidates{std::filesystem::path(*path)};
    if (!candidates.front().is_absolute()) {
      candidates = {folder / *path, folder.parent_path() / "Bit" / *path};
    }
    const auto found = std::find_if(candidates.begin(), candidates.end(), [](const std::filesystem::path& p) {
      std::error_code ec;
      return std::filesystem::is_regular_file(p, ec);
    });
    if (found == candidates.end()) {
      std::string looked;
      for (const auto& c : candidates) looked += (looked.empty() ? "" : ", ") + c.string();
      throw InputError(location_of(entry["path"], name), "tool bit '" + *path + "' not found (looked at " + looked + ")");
    }
    tools.push_back(parse_freecad_tool_bit(read_text_file(*found), found->string(), number));
    where.push_back(location_of(entry["nr"], name));
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
