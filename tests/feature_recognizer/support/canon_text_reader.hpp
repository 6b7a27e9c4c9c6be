#pragma once
// Test support: reads the canonical-call text LinuxCNC's standalone rs274 prints
// (`   25 N..... STRAIGHT_TRAVERSE(91.9000, -13.5000, 100.0000, 0.0000, 0.0000, 0.0000)`) into
// ncbridge::canonical::Call values. Only the calls toolpath recognition needs are decoded; the
// others are skipped. Source.line is the line of the text file.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/canonical/call.hpp"

namespace ncbridge::test_support {

std::vector<canonical::Call> parse_canon_text(std::string_view text, const std::string& file_name);
std::vector<canonical::Call> read_canon_text(const std::filesystem::path& file);

}  // namespace ncbridge::test_support
