#pragma once
// The version of this ncbridge build (CMake's PROJECT_VERSION): `ncbridge --version`, the
// reports, and the Part 21 FILE_NAME of every file ncbridge writes.
#include <string_view>

namespace ncbridge {

std::string_view version();          // "0.1.0"
std::string_view version_string();   // "ncbridge 0.1.0"

}  // namespace ncbridge
