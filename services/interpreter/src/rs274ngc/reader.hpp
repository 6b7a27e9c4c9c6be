#pragma once
// RS274/NGC front-end: one line of LinuxCNC-dialect text -> the neutral Block.
// Case-insensitive outside comments; spaces and tabs between tokens are ignored.
#include <cstdint>
#include <string>
#include <string_view>

#include "block_model.hpp"

namespace ncbridge::interpreter::rs274ngc {

// Parses `text` (line `line` of `file`) into `block`. With `control_only`, a line without an
// O-word is only scanned for its N word and O-word (used while skipping lines, where LinuxCNC
// does not look further either). Throws InputError with file, line and column.
void read_block(std::string_view text, std::uint32_t line, const std::string& file, Block& block,
                bool control_only = false);

}  // namespace ncbridge::interpreter::rs274ngc
