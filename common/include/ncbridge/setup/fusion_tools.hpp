#pragma once
// A Fusion 360 (Autodesk Fusion) tool library as its library manager exports it: JSON
// {"data": [tool, ...]}, each tool with its type, unit, geometry (DC, OAL, LCF, NOF, RE, SIG,
// TP), post-process number and start values. docs/formats/tools.md.
#include <string>
#include <string_view>

#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::setup {

// Holders in the library are skipped; tool types without an ISO 14649 counterpart here (thread
// mill, form mill, probe, ...) are read without a type. Errors name the file, line and column.
ToolList parse_fusion_tool_library(std::string_view text, const std::string& file_name_for_errors);

}  // namespace ncbridge::setup
