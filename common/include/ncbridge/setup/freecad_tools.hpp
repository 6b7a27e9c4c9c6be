#pragma once
// FreeCAD's tool data (the CAM workbench's Tools/ folder): a tool bit (.fctb, JSON: a name, the
// shape it is made from and the shape's parameters as quantities with units, "6.000 mm") and a
// tool library (.fctl, JSON: tool numbers and the bit files they are). docs/formats/tools.md.
#include <filesystem>
#include <string>
#include <string_view>

#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::setup {

// One bit as tool `number`. The shape names the kind (endmill, ballend, bullnose, drill,
// chamfer, v-bit, tap; others are read without a type). Errors name the file, line and column.
Tool parse_freecad_tool_bit(std::string_view text, const std::string& file_name_for_errors, int number);

// A library: each entry's bit file is found as FreeCAD finds it (an absolute path, beside the
// library, or in the Bit folder beside the library's folder).
ToolList read_freecad_tool_library(const std::filesystem::path& file);

// A bit on its own is tool 1, the number FreeCAD gives a bit added to a job without a library.
ToolList read_freecad_tool_bit(const std::filesystem::path& file);

}  // namespace ncbridge::setup
