#pragma once
// Files of the CLI tests: an emptied directory per test under the build tree, and a file's bytes.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace ncbridge::testing {

// build/test_output/GROUP/NAME, empty. Each test file has a group of its own, so tests of two
// files that run at once never share a directory.
inline std::filesystem::path fresh_test_directory(const std::string& group, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(NCBRIDGE_BINARY_DIR) / "test_output" / group / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace ncbridge::testing
