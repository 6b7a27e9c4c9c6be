#pragma once
// A warning of a command run: printed on stderr (errors.hpp's style), listed in the report and
// the HTML page, an error under --strict.
#include <string>

#include "ncbridge/common/error.hpp"

namespace ncbridge::cli {

struct Warning {
  // "feed", "outside_stock", "security_plane", "units", "tool_type" (setup_checks.hpp);
  // "representation" (what the CC1 builder could not represent exactly), "recognition" (CC2),
  // "input" (entities of a CC1 file that were read but not kept).
  std::string kind;
  SourceLocation where;
  std::string message;
};

}  // namespace ncbridge::cli
