#include "ncbridge/common/version.hpp"

namespace ncbridge {

std::string_view version() { return NCBRIDGE_VERSION; }

std::string_view version_string() { return "ncbridge " NCBRIDGE_VERSION; }

}  // namespace ncbridge
