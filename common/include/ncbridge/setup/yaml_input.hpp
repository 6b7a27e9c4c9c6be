#pragma once
// Helpers for the small JSON/YAML configuration files (tools, stock): yaml-cpp reads both and
// keeps line/column marks, so every error names the place in the file.
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "ncbridge/common/error.hpp"

namespace ncbridge::setup {

std::string read_text_file(const std::filesystem::path& file);  // throws InputError if unreadable
YAML::Node parse_yaml_document(std::string_view text, const std::string& file);
SourceLocation location_of(const YAML::Node& node, const std::string& file);

int required_int(const YAML::Node& map, const char* key, const std::string& file);
std::optional<double> optional_number(const YAML::Node& map, const char* key, const std::string& file);
std::optional<std::string> optional_string(const YAML::Node& map, const char* key, const std::string& file);

}  // namespace ncbridge::setup
