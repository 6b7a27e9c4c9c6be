// Cutter radius compensation through the whole interpreter: every program in comp_cases/ goes
// through `ncbridge canon` with the cases' tool table, and the listing must match what LinuxCNC's
// rs274 printed for it (NAME.canon), call for call, as in the golden tests. Where rs274 stopped on
// an error (NAME.error: message, then the offending block), ncbridge must stop too, with the
// same message, on the line holding that block.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/canon_listing.hpp"
#include "support/run_program.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kCases = fs::path(NCBRIDGE_SOURCE_DIR) / "tests/interpreter/comp_cases";

std::vector<std::string> read_lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kCases)) {
    if (entry.path().extension() == ".ngc") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class CompCaseThroughCanon : public ::testing::TestWithParam<std::string> {};

TEST_P(CompCaseThroughCanon, ListingMatchesRs274) {
  const std::string name = GetParam();
  const fs::path program = kCases / (name + ".ngc");
  const auto run = ncbridge::testing::run_program({NCBRIDGE_EXECUTABLE, "canon", program.string(), "--tool-table",
                                                   (kCases / "tools.tbl").string(), "--tool-table-units", "inch"});
  const auto expected = ncbridge::testing::parse_canon_listing(read_file(kCases / (name + ".canon")));
  ASSERT_FALSE(expected.empty()) << name << ".canon is empty";
  const auto comparison =
      ncbridge::testing::compare_canon_listings(expected, ncbridge::testing::parse_canon_listing(run.out));
  EXPECT_TRUE(comparison.equal) << name << ": " << comparison.report << "\nstderr: " << run.err;

  const fs::path error_file = kCases / (name + ".error");
  if (!fs::exists(error_file)) {
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return;
  }
  const auto error = read_lines(error_file);
  ASSERT_GE(error.size(), 2u) << error_file << " needs the message and the block";
  EXPECT_EQ(run.exit_code, 1) << "rs274 stopped with: " << error[0];
  const auto lines = read_lines(program);
  const auto block = std::find(lines.begin(), lines.end(), error[1]);
  ASSERT_NE(block, lines.end()) << "the block rs274 names is not in the program: " << error[1];
  const std::string where = program.string() + ":" + std::to_string(block - lines.begin() + 1) + ":";
  EXPECT_NE(run.err.find("ncbridge: error: " + where), std::string::npos) << "expected the error at " << where << ", got: " << run.err;
  EXPECT_NE(run.err.find(": " + error[0]), std::string::npos) << "expected: " << error[0] << "\ngot: " << run.err;
}

INSTANTIATE_TEST_SUITE_P(Rs274, CompCaseThroughCanon, ::testing::ValuesIn(case_names()),
                         [](const ::testing::TestParamInfo<std::string>& case_info) { return case_info.param; });

TEST(CompCasesThroughCanon, CoverTheCaseFolder) { EXPECT_GE(case_names().size(), 30u); }

}  // namespace
