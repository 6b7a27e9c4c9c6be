// Golden tests of the RS274/NGC interpreter: each program in tests/interpreter/golden/cases.txt
// goes through `ncbridge canon`, and the calls must match what LinuxCNC's rs274 printed for it
// (expected/NAME.canon, made by golden/regenerate.sh): same calls in the same order, same N
// column, numbers within 1e-4.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "ncbridge/setup/tool_list.hpp"
#include "support/canon_listing.hpp"
#include "support/golden_cases.hpp"
#include "support/run_program.hpp"

namespace fs = std::filesystem;
using ncbridge::testing::GoldenCase;

namespace {

const fs::path kGoldenDir = fs::path(NCBRIDGE_SOURCE_DIR) / "tests/interpreter/golden";

const std::vector<GoldenCase>& golden_cases() {
  static const std::vector<GoldenCase> cases = [] {
    try {
      return ncbridge::testing::read_golden_cases(kGoldenDir, NCBRIDGE_SHARED_DIR);
    } catch (const std::exception&) {
      return std::vector<GoldenCase>{};  // GoldenCatalogue.CasesFileReads reports the reason
    }
  }();
  return cases;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> canon_command(const GoldenCase& c) {
  std::vector<std::string> argv = {NCBRIDGE_EXECUTABLE, "canon", c.program.string()};
  argv.insert(argv.end(), c.tool_arguments.begin(), c.tool_arguments.end());
  if (!c.subroutine_path.empty()) {
    argv.push_back("--subroutine-path");
    argv.push_back(c.subroutine_path.string());
  }
  return argv;
}

ncbridge::setup::ToolList ncbridge_tools(const GoldenCase& c) {
  using ncbridge::setup::LengthUnits;
  if (c.tools_kind == "tools-json") return ncbridge::setup::read_tool_list(c.tools_file);
  return ncbridge::setup::read_linuxcnc_tool_table(
      c.tools_file, c.tools_kind == "tool-table-mm" ? LengthUnits::Millimeters : LengthUnits::Inches);
}

}  // namespace

TEST(GoldenCatalogue, CasesFileReads) {
  EXPECT_NO_THROW(ncbridge::testing::read_golden_cases(kGoldenDir, NCBRIDGE_SHARED_DIR));
  EXPECT_GE(golden_cases().size(), 70u);
}

TEST(GoldenCatalogue, EveryProgramHasACaseAndEveryCaseItsFiles) {
  std::set<fs::path> listed;
  for (const auto& c : golden_cases()) {
    listed.insert(c.program);
    EXPECT_TRUE(fs::exists(c.program)) << c.name << ": no program " << c.program;
    EXPECT_TRUE(fs::exists(c.expected)) << c.name << ": no expected output (run golden/regenerate.sh)";
    EXPECT_TRUE(fs::exists(c.rs274_tool_table)) << c.name << ": no tool table " << c.rs274_tool_table;
  }
  for (const auto& entry : fs::directory_iterator(kGoldenDir / "programs")) {
    if (entry.path().extension() == ".ngc") {
      EXPECT_TRUE(listed.count(entry.path())) << entry.path().filename() << " is not in cases.txt";
    }
  }
}

class GoldenProgram : public ::testing::TestWithParam<GoldenCase> {};

// rs274 reads its table in inches; ncbridge reads the case's own tool file: both must describe
// the same tools, or a disagreement would be the test data's fault.
TEST_P(GoldenProgram, ToolFilesDescribeTheSameTools) {
  const GoldenCase& c = GetParam();
  const auto rs274 = ncbridge::setup::read_linuxcnc_tool_table(c.rs274_tool_table,
                                                               ncbridge::setup::LengthUnits::Inches);
  const auto ours = ncbridge_tools(c);
  ASSERT_EQ(rs274.tools().size(), ours.tools().size());
  for (const auto& tool : rs274.tools()) {
    const auto* same = ours.find(tool.number);
    ASSERT_NE(same, nullptr) << "tool " << tool.number << " missing from " << c.tools_file;
    EXPECT_NEAR(tool.diameter, same->diameter, 1e-4) << "tool " << tool.number;
    EXPECT_NEAR(tool.length, same->length, 1e-4) << "tool " << tool.number;
  }
}

TEST_P(GoldenProgram, CanonicalCallsMatchRs274) {
  const GoldenCase& c = GetParam();
  const auto run = ncbridge::testing::run_program(canon_command(c));
  ASSERT_EQ(run.exit_code, 0) << "ncbridge canon failed on " << c.program << ":\n" << run.err;
  const auto expected = ncbridge::testing::parse_canon_listing(read_file(c.expected));
  ASSERT_FALSE(expected.empty()) << c.expected;
  const auto actual = ncbridge::testing::parse_canon_listing(run.out);
  const auto comparison = ncbridge::testing::compare_canon_listings(expected, actual);
  EXPECT_TRUE(comparison.equal) << c.name << ": " << comparison.report;
}

INSTANTIATE_TEST_SUITE_P(Rs274, GoldenProgram, ::testing::ValuesIn(golden_cases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& param_info) { return param_info.param.name; });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(GoldenProgram);
