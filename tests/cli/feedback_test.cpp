// What a command says besides results and errors (cli/src/feedback.hpp): the progress line
// (after a second, redrawn in place, erased at the end), the one-line summary, -q and -v, and
// the version in the report and the Part 21 FILE_NAME.
#include <fcntl.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_test_files.hpp"
#include "feedback.hpp"
#include "support/run_program.hpp"

namespace ncbridge::cli {
namespace {

namespace fs = std::filesystem;
using ncbridge::testing::ProgramRun;

const fs::path kPlate = fs::path(NCBRIDGE_SOURCE_DIR) / "examples" / "plate";

fs::path fresh_directory(const std::string& name) { return ncbridge::testing::fresh_test_directory("cli_feedback", name); }

using ncbridge::testing::slurp;

// Standard error of this process, captured into a file while alive.
class CapturedStderr {
 public:
  explicit CapturedStderr(const fs::path& file) : file_(file) {
    std::fflush(stderr);
    saved_ = ::dup(2);
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 2);
    ::close(fd);
  }
  std::string text() {
    std::fflush(stderr);
    ::dup2(saved_, 2);
    ::close(saved_);
    saved_ = -1;
    return slurp(file_);
  }
  ~CapturedStderr() {
    if (saved_ >= 0) text();
  }

 private:
  fs::path file_;
  int saved_ = -1;
};

TEST(Progress, ShowsAfterASecondRedrawsInPlaceAndIsErased) {
  const fs::path dir = fresh_directory("progress");
  CapturedStderr captured(dir / "stderr");
  {
    Progress progress(true);
    for (int i = 0; i < 0x4000; ++i) progress.tick([] { return std::string("line 16384"); });  // one text made
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    progress.set("recognising features");
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }  // stopped and erased
  const std::string text = captured.text();
  EXPECT_NE(text.find("\rline 16384\033[K"), std::string::npos) << text;
  EXPECT_NE(text.find("\rrecognising features\033[K"), std::string::npos) << text;
  EXPECT_TRUE(text.ends_with("\r\033[K")) << text;
  EXPECT_EQ(text.find('\n'), std::string::npos) << text;  // one line, redrawn
}

TEST(Progress, AShortRunOrADisabledOneDrawsNothing) {
  const fs::path dir = fresh_directory("progress_short");
  CapturedStderr captured(dir / "stderr");
  {
    Progress quick(true);
    quick.set("converting");
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
  }
  {
    Progress off(false);
    off.set("converting");
    std::this_thread::sleep_for(std::chrono::milliseconds(1300));
  }
  EXPECT_EQ(captured.text(), "");
}

std::vector<std::string> plate_convert(const fs::path& dir, std::vector<std::string> more) {
  std::vector<std::string> argv{NCBRIDGE_EXECUTABLE, "convert", (kPlate / "plate.ngc").string(), "--tools",
                                (kPlate / "tools.json").string(), "--stock", (kPlate / "stock.json").string(),
                                "-o", (dir / "plate.stp").string()};
  argv.insert(argv.end(), more.begin(), more.end());
  return argv;
}

TEST(Feedback, ASummaryLineOnSuccessQuietAndVerbose) {
  const fs::path dir = fresh_directory("summary");
  const ProgramRun normal = ncbridge::testing::run_program(plate_convert(dir, {"--level", "cc2"}));
  ASSERT_EQ(normal.exit_code, 0) << normal.err;
  EXPECT_TRUE(normal.err.starts_with("ncbridge: " + (dir / "plate.stp").string() +
                                     ": CC2, 6 features, 6 workingsteps, 3 tools, 0 warnings, "))
      << normal.err;
  EXPECT_EQ(std::count(normal.err.begin(), normal.err.end(), '\n'), 1) << normal.err;
  EXPECT_EQ(normal.err.find('\r'), std::string::npos) << "progress on a file: " << normal.err;

  for (const std::vector<std::string>& quiet : {std::vector<std::string>{"-q"}, std::vector<std::string>{"--quiet"}}) {
    const ProgramRun r = ncbridge::testing::run_program(plate_convert(dir, quiet));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
  }
  std::vector<std::string> before{NCBRIDGE_EXECUTABLE, "-q"};  // before the command's name too
  const auto after = plate_convert(dir, {});
  before.insert(before.end(), after.begin() + 1, after.end());
  EXPECT_EQ(ncbridge::testing::run_program(before).err, "");

  // Warnings stay with -q.
  const ProgramRun warned = ncbridge::testing::run_program(plate_convert(dir, {"-q", "--security-plane", "-5"}));
  EXPECT_NE(warned.err.find("ncbridge: warning: "), std::string::npos) << warned.err;
  EXPECT_EQ(warned.err.find("ncbridge: " + (dir / "plate.stp").string() + ": CC1"), std::string::npos) << warned.err;

  const ProgramRun verbose = ncbridge::testing::run_program(plate_convert(dir, {"-v", "--report", (dir / "r.json").string()}));
  ASSERT_EQ(verbose.exit_code, 0) << verbose.err;
  EXPECT_NE(verbose.err.find("ncbridge: read 3 tools from "), std::string::npos) << verbose.err;
  EXPECT_NE(verbose.err.find("stock 80 x 60 x 22 mm (X0..80 Y0..60 Z-20..2)"), std::string::npos) << verbose.err;
  EXPECT_NE(verbose.err.find("ncbridge: interpreted and built 137 canonical calls in "), std::string::npos) << verbose.err;
  EXPECT_NE(verbose.err.find("ncbridge: wrote " + (dir / "plate.stp").string() + " ("), std::string::npos) << verbose.err;
  EXPECT_NE(verbose.err.find(": CC1, 10 workingsteps, 3 tools, 0 warnings, "), std::string::npos) << verbose.err;
}

TEST(Feedback, AShortRunOnATerminalShowsNoProgressLine) {
  // `script` gives the command a terminal; the plate converts in well under a second.
  const fs::path dir = fresh_directory("terminal");
  std::string command;
  for (const auto& a : plate_convert(dir, {})) command += "'" + a + "' ";
  const ProgramRun r = ncbridge::testing::run_program({"/usr/bin/script", "-qec", command, (dir / "typescript").string()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find(": CC1, 10 workingsteps"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("converting:"), std::string::npos) << r.out;
}

TEST(Version, InTheReportAndTheFileName) {
  const fs::path dir = fresh_directory("version");
  const ProgramRun version = ncbridge::testing::run_program({NCBRIDGE_EXECUTABLE, "--version"});
  ASSERT_EQ(version.exit_code, 0);
  const std::string number = version.out.substr(std::string("ncbridge ").size(), version.out.find('\n') - 9);
  ASSERT_FALSE(number.empty());
  for (const char* level : {"cc1", "cc2"}) {
    const ProgramRun r = ncbridge::testing::run_program(plate_convert(dir, {"--level", level, "--report", (dir / "r.json").string()}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(slurp(dir / "r.json")).at("ncbridge_version"), number);
    // FILE_NAME(name, time_stamp, author, organization, preprocessor_version, originating_system, authorization)
    EXPECT_NE(slurp(dir / "plate.stp").find("(''),(''),'ncbridge " + number + "','ncbridge " + number + "','');"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace ncbridge::cli
