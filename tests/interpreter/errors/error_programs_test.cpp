// Every program in tests/interpreter/errors/ is wrong in one way, named in its header:
//   (expect-error: LINE:COLUMN: fragment|fragment...)
// `ncbridge canon` must exit non-zero (not crash) and print `ncbridge: error: file:LINE:COLUMN: message`
// with one of the fragments in the message (case-insensitive). COLUMN `*` accepts any column.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>

#include "support/run_program.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kErrorsDir = fs::path(NCBRIDGE_SOURCE_DIR) / "tests/interpreter/errors";
constexpr const char* kTimeoutSeconds = "20";
const fs::path kMetricTools = fs::path(NCBRIDGE_SOURCE_DIR) / "tests/interpreter/golden/tools/metric.mm.tbl";

struct ErrorCase {
  std::string name;
  fs::path program;
  bool has_expectation = false;
  unsigned line = 0;
  unsigned column = 0;  // 0 = any
  std::vector<std::string> fragments;
};

void PrintTo(const ErrorCase& c, std::ostream* os) { *os << c.name; }

ErrorCase read_error_case(const fs::path& program) {
  ErrorCase c;
  c.name = program.stem().string();
  c.program = program;
  std::ifstream in(program);
  std::string text;
  static const std::regex header(R"(\(expect-error: (\d+):(\d+|\*): (.*)\))");
  std::smatch m;
  for (int i = 0; i < 5 && std::getline(in, text); ++i) {
    if (!std::regex_search(text, m, header)) continue;
    c.has_expectation = true;
    c.line = static_cast<unsigned>(std::stoul(m[1]));
    c.column = m[2] == "*" ? 0 : static_cast<unsigned>(std::stoul(m[2]));
    std::string fragments = m[3];
    for (std::size_t start = 0;;) {
      const auto bar = fragments.find('|', start);
      c.fragments.push_back(fragments.substr(start, bar - start));
      if (bar == std::string::npos) break;
      start = bar + 1;
    }
    break;
  }
  return c;
}

std::vector<ErrorCase> error_cases() {
  std::vector<ErrorCase> cases;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(kErrorsDir, ec)) {
    if (entry.path().extension() == ".ngc") cases.push_back(read_error_case(entry.path()));
  }
  std::sort(cases.begin(), cases.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return cases;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return s;
}

}  // namespace

TEST(ErrorCatalogue, HasErrorPrograms) { EXPECT_GE(error_cases().size(), 20u); }

class ErrorProgram : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(ErrorProgram, FailsWithFileLineColumnAndMessage) {
  const ErrorCase& c = GetParam();
  ASSERT_TRUE(c.has_expectation) << c.program << " has no (expect-error: LINE:COLUMN: text) header";
  // Endless loops are among the cases: a bounded run, whose calls nobody reads.
  std::vector<std::string> argv = {NCBRIDGE_EXECUTABLE, "canon", c.program.string(), "--tool-table",
                                   kMetricTools.string(), "--tool-table-units", "mm"};
  const auto timeout = ncbridge::testing::find_on_path("timeout");
  if (!timeout.empty()) argv.insert(argv.begin(), {timeout.string(), kTimeoutSeconds});
  ncbridge::testing::RunOptions options;
  options.discard_output = true;
  const auto run = ncbridge::testing::run_program(argv, options);
  ASSERT_NE(run.exit_code, 124) << "ncbridge did not finish within " << kTimeoutSeconds << " s on " << c.program;
  ASSERT_NE(run.exit_code, 0) << "ncbridge accepted " << c.program;
  ASSERT_LT(run.exit_code, 128) << "ncbridge was killed by a signal on " << c.program << ":\n" << run.err;

  static const std::regex diagnostic(R"(ncbridge: error: (.*):(\d+):(\d+): (.*))");
  std::smatch m;
  std::string line_text;
  bool found = false;
  for (std::size_t start = 0; start < run.err.size();) {
    const auto eol = run.err.find('\n', start);
    line_text = run.err.substr(start, eol - start);
    if (std::regex_match(line_text, m, diagnostic)) { found = true; break; }
    if (eol == std::string::npos) break;
    start = eol + 1;
  }
  ASSERT_TRUE(found) << "no `ncbridge: error: file:line:column: message` line in:\n" << run.err;
  EXPECT_TRUE(fs::path(m[1].str()).filename() == c.program.filename()) << line_text;
  EXPECT_EQ(std::stoul(m[2]), c.line) << line_text;
  if (c.column != 0) {
    EXPECT_EQ(std::stoul(m[3]), c.column) << line_text;
  }
  EXPECT_GE(std::stoul(m[3]), 1u) << line_text;
  const std::string message = lower(m[4]);
  const bool mentions = std::any_of(c.fragments.begin(), c.fragments.end(),
                                    [&](const std::string& f) { return message.find(lower(f)) != std::string::npos; });
  EXPECT_TRUE(mentions) << "message should mention one of its expected words: " << line_text;
}

INSTANTIATE_TEST_SUITE_P(Rs274, ErrorProgram, ::testing::ValuesIn(error_cases()),
                         [](const ::testing::TestParamInfo<ErrorCase>& param_info) { return param_info.param.name; });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(ErrorProgram);
