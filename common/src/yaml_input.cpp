#include "ncbridge/setup/yaml_input.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace ncbridge::setup {

std::string read_text_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError({file.string(), 0, 0}, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return std::move(ss).str();
}

YAML::Node parse_yaml_document(std::string_view text, const std::string& file) {
  try {
    return YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    throw InputError({file, static_cast<std::uint32_t>(e.mark.line + 1), static_cast<std::uint32_t>(e.mark.column + 1)},
                     e.msg);
  }
}

SourceLocation location_of(const YAML::Node& node, const std::string& file) {
  const YAML::Mark m = node.Mark();
  if (m.is_null()) return {file, 0, 0};
  return {file, static_cast<std::uint32_t>(m.line + 1), static_cast<std::uint32_t>(m.column + 1)};
}

std::optional<double> optional_number(const YAML::Node& map, const char* key, const std::string& file) {
  const YAML::Node n = map[key];
  if (!n || n.IsNull()) return std::nullopt;
  double v = 0;
  if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !std::isfinite(v)) {
    throw InputError(location_of(n, file), std::string("'") + key + "' must be a number");
  }
  return v;
}

int required_int(const YAML::Node& map, const char* key, const std::string& file) {
  const YAML::Node n = map[key];
  if (!n) throw InputError(location_of(map, file), std::string("missing '") + key + "'");
  int v = 0;
  if (!n.IsScalar() || !YAML::convert<int>::decode(n, v)) {
    throw InputError(location_of(n, file), std::string("'") + key + "' must be an integer");
  }
  return v;
}

std::optional<std::string> optional_string(const YAML::Node& map, const char* key, const std::string& file) {
  const YAML::Node n = map[key];
  if (!n || n.IsNull()) return std::nullopt;
  if (!n.IsScalar()) throw InputError(location_of(n, file), std::string("'") + key + "' must be a string");
  return n.Scalar();
}

}  // namespace ncbridge::setup
