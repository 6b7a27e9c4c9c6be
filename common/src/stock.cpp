#include "ncbridge/setup/stock.hpp"

#include "ncbridge/common/error.hpp"
#include "ncbridge/setup/yaml_input.hpp"

namespace ncbridge::setup {

namespace {
std::array<double, 3> read_point(const YAML::Node& map, const char* key, const std::string& file, double scale) {
  const YAML::Node n = map[key];
  if (!n) throw InputError(location_of(map, file), std::string("stock: missing '") + key + "' ([x, y, z])");
  if (!n.IsSequence() || n.size() != 3) {
    throw InputError(location_of(n, file), std::string("stock: '") + key + "' must be [x, y, z]");
  }
  std::array<double, 3> p{};
  for (std::size_t i = 0; i < 3; ++i) {
    double v = 0;
    if (!n[i].IsScalar() || !YAML::convert<double>::decode(n[i], v)) {
      throw InputError(location_of(n[i], file), std::string("stock: '") + key + "' must hold numbers");
    }
    p[i] = v * scale;
  }
  return p;
}
}  // namespace

Stock parse_stock(std::string_view text, const std::string& file) {
  const YAML::Node root = parse_yaml_document(text, file);
  if (!root.IsMap()) throw InputError(location_of(root, file), "stock: expected an object");
  double scale = 1.0;
  LengthUnits units_given = LengthUnits::Millimeters;
  if (auto units = optional_string(root, "units", file)) {
    if (*units == "inch" || *units == "in" || *units == "inches") {
      scale = 25.4;
      units_given = LengthUnits::Inches;
    } else if (*units != "mm") {
      throw InputError(location_of(root["units"], file), "stock: units must be \"mm\" or \"inch\"");
    }
  }
  if (auto shape = optional_string(root, "shape", file); shape && *shape != "block") {
    throw InputError(location_of(root["shape"], file), "stock: only shape \"block\" is supported, not \"" + *shape + "\"");
  }
  Stock s;
  s.file_units = units_given;
  s.min = read_point(root, "min", file, scale);
  s.max = read_point(root, "max", file, scale);
  for (int i = 0; i < 3; ++i) {
    if (!(s.max[i] > s.min[i])) {
      throw InputError(location_of(root["max"], file), "stock: max must be greater than min on every axis");
    }
  }
  return s;
}

Stock read_stock(const std::filesystem::path& file) { return parse_stock(read_text_file(file), file.string()); }

}  // namespace ncbridge::setup
