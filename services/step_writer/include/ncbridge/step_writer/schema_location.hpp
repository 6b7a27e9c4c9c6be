#pragma once
// Where the ISO 14649 EXPRESS schema is found when the user names none. The schema text is ISO's
// and is not carried in the repository; it is looked up, in order:
//   1. $NCBRIDGE_ISO14649_SCHEMA
//   2. <dir of the executable>/../share/ncbridge/iso14649.exp  (an installed layout)
//   3. the shared/ folder the build was configured with (development checkouts)
#include <filesystem>
#include <optional>

namespace ncbridge::step_writer {

// `executable` is argv[0] or /proc/self/exe; may be empty. Nullopt when no candidate exists.
std::optional<std::filesystem::path> find_iso14649_schema(const std::filesystem::path& executable);

}  // namespace ncbridge::step_writer
