#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "ncbridge/step_writer/atomic_file.hpp"

namespace fs = std::filesystem;
using ncbridge::step_writer::write_file_atomically;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh_dir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("ncbridge_p21_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST(AtomicFile, WritesThenReplacesAndLeavesNoTemporary) {
  fs::path dir = fresh_dir("atomic");
  fs::path target = dir / "out.stp";
  write_file_atomically(target, "first");
  EXPECT_EQ(slurp(target), "first");
  write_file_atomically(target, std::string(100000, 'x'));
  EXPECT_EQ(slurp(target), std::string(100000, 'x'));
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);
  fs::remove_all(dir);
}

TEST(AtomicFile, FailureLeavesTheOldFileAndNoTemporary) {
  fs::path dir = fresh_dir("atomic_fail");
  fs::path target = dir / "out.stp";
  write_file_atomically(target, "old");
  // Renaming a file over a non-empty directory fails: the old content must survive.
  fs::path blocked = dir / "blocked";
  fs::create_directories(blocked / "inside");
  EXPECT_THROW(write_file_atomically(blocked, "new"), std::system_error);
  EXPECT_EQ(slurp(target), "old");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 2u);  // out.stp and blocked/
  EXPECT_THROW(write_file_atomically(dir / "no_such_dir" / "x.stp", "new"), std::system_error);
  fs::remove_all(dir);
}
