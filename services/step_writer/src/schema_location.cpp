#include <cstdlib>
#include <system_error>

#include "ncbridge/step_writer/schema_location.hpp"

namespace ncbridge::step_writer {

std::optional<std::filesystem::path> find_iso14649_schema(const std::filesystem::path& executable) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (const char* env = std::getenv("NCBRIDGE_ISO14649_SCHEMA"); env && *env) {
    if (fs::is_regular_file(env, ec)) return fs::path(env);
    return std::nullopt;  // named but missing: do not silently use another schema
  }
  if (!executable.empty()) {
    fs::path exe = fs::weakly_canonical(executable, ec);
    if (!ec) {
      fs::path installed = exe.parent_path().parent_path() / "share" / "ncbridge" / "iso14649.exp";
      if (fs::is_regular_file(installed, ec)) return installed;
    }
  }
#ifdef NCBRIDGE_DEFAULT_ISO14649_SCHEMA
  fs::path development(NCBRIDGE_DEFAULT_ISO14649_SCHEMA);
  if (fs::is_regular_file(development, ec)) return development;
#endif
  return std::nullopt;
}

}  // namespace ncbridge::step_writer
