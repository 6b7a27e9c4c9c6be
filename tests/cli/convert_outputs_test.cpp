// The outputs of `ncbridge convert` (and canon/check/diff inputs) as a user meets them: "-" for
// standard input and output, /dev/stdout and /dev/null left as they are, FIFOs written through,
// every output path checked before work starts, and the outputs of a run together or not at all.
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_test_files.hpp"
#include "support/run_program.hpp"

namespace ncbridge::cli {
namespace {

namespace fs = std::filesystem;
using ncbridge::testing::ProgramRun;
using ncbridge::testing::RunOptions;

const fs::path kPlate = fs::path(NCBRIDGE_SOURCE_DIR) / "examples" / "plate";
const std::string kEpoch = "SOURCE_DATE_EPOCH=1700000000";

fs::path fresh_directory(const std::string& name) { return ncbridge::testing::fresh_test_directory("cli_convert_outputs", name); }

using ncbridge::testing::slurp;

void put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> convert_args(const std::string& program, std::vector<std::string> more) {
  std::vector<std::string> argv{NCBRIDGE_EXECUTABLE, "convert", program, "--tools", (kPlate / "tools.json").string(),
                                "--stock", (kPlate / "stock.json").string()};
  argv.insert(argv.end(), more.begin(), more.end());
  return argv;
}

ProgramRun run(const std::vector<std::string>& argv, const fs::path& stdin_file = {}) {
  RunOptions options;
  options.extra_environment = {kEpoch};
  options.standard_input = stdin_file;
  return ncbridge::testing::run_program(argv, options);
}

TEST(ConvertOutputs, DashWritesStandardOutputAndReadsStandardInput) {
  const fs::path dir = fresh_directory("dash");
  const std::string program = (kPlate / "plate.ngc").string();
  const ProgramRun to_file = run(convert_args(program, {"-o", (dir / "plate.stp").string()}));
  ASSERT_EQ(to_file.exit_code, 0) << to_file.err;
  const std::string expected = slurp(dir / "plate.stp");
  ASSERT_NE(expected.find("ISO-10303-21;"), std::string::npos);

  const ProgramRun to_stdout = run(convert_args(program, {"-o", "-"}));
  ASSERT_EQ(to_stdout.exit_code, 0) << to_stdout.err;
  EXPECT_EQ(to_stdout.out, expected);  // FILE_NAME: the program's name with .stp
  EXPECT_FALSE(fs::exists(fs::current_path() / "-"));

  // A program on standard input, CC1 (streamed) and CC2.
  const ProgramRun piped = run(convert_args("-", {"-o", "-"}), kPlate / "plate.ngc");
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  std::string from_stdin = piped.out;
  const auto name_at = from_stdin.find("FILE_NAME('stdin.stp'");
  ASSERT_NE(name_at, std::string::npos) << from_stdin.substr(0, 400);
  from_stdin.replace(name_at, std::string("FILE_NAME('stdin.stp'").size(), "FILE_NAME('plate.stp'");
  EXPECT_EQ(from_stdin, expected);

  const ProgramRun cc2 = run(convert_args("-", {"--level", "cc2", "-o", (dir / "cc2.stp").string(), "--report",
                                                (dir / "cc2.json").string()}),
                             kPlate / "plate.ngc");
  ASSERT_EQ(cc2.exit_code, 0) << cc2.err;
  EXPECT_NE(slurp(dir / "cc2.json").find("\"program\": \"<stdin>\""), std::string::npos);
  EXPECT_NE(slurp(dir / "cc2.stp").find("CLOSED_POCKET"), std::string::npos);
}

TEST(ConvertOutputs, DevStdoutIsStandardOutputAndIsNotReplaced) {
  struct stat before {};
  ASSERT_EQ(::lstat("/dev/stdout", &before), 0);
  const ProgramRun r = run(convert_args((kPlate / "plate.ngc").string(), {"-o", "/dev/stdout"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("ISO-10303-21;", 0), 0u) << r.out.substr(0, 200);
  EXPECT_NE(r.out.find("END-ISO-10303-21;"), std::string::npos);
  struct stat after {};
  ASSERT_EQ(::lstat("/dev/stdout", &after), 0);
  EXPECT_EQ(after.st_mode & S_IFMT, before.st_mode & S_IFMT);
  EXPECT_EQ(after.st_ino, before.st_ino);
}

TEST(ConvertOutputs, DevNullStaysACharacterDevice) {
  const ProgramRun r = run(convert_args((kPlate / "plate.ngc").string(),
                                        {"--level", "cc2", "-o", "/dev/null", "--report", "/dev/null", "--html", "/dev/null"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  struct stat st {};
  ASSERT_EQ(::lstat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_EQ(st.st_rdev, makedev(1, 3));
}

TEST(ConvertOutputs, AFifoIsWrittenThroughNotReplaced) {
  const fs::path dir = fresh_directory("fifo");
  const fs::path fifo = dir / "out.stp";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = slurp(fifo); });
  const ProgramRun r = run(convert_args((kPlate / "plate.ngc").string(), {"-o", fifo.string()}));
  reader.join();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(received.find("END-ISO-10303-21;"), std::string::npos);
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST(ConvertOutputs, ASymlinkIsFollowedAndKept) {
  const fs::path dir = fresh_directory("symlink");
  fs::create_directories(dir / "results");
  put(dir / "results" / "plate.stp", "old");
  fs::create_symlink("results/plate.stp", dir / "latest.stp");
  const ProgramRun r = run(convert_args((kPlate / "plate.ngc").string(), {"-o", (dir / "latest.stp").string()}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir / "latest.stp"));
  EXPECT_EQ(slurp(dir / "results" / "plate.stp").rfind("ISO-10303-21;", 0), 0u);
}

// A bad --report or --html path is found before work starts: exit 3, no .stp, the old one kept.
TEST(ConvertOutputs, ABadReportOrHtmlPathLeavesNoStpFile) {
  const fs::path dir = fresh_directory("bad_report");
  put(dir / "old.stp", "old");
  put(dir / "a_file", "x");
  const std::string program = (kPlate / "plate.ngc").string();
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases{
      {{"-o", (dir / "new.stp").string(), "--report", (dir / "missing" / "r.json").string()}, "does not exist (--report)"},
      {{"-o", (dir / "old.stp").string(), "--report", (dir / "missing" / "r.json").string()}, "does not exist (--report)"},
      {{"--level", "cc2", "-o", (dir / "new.stp").string(), "--html", (dir / "a_file" / "p.html").string()},
       "is not a directory (--html)"},
      {{"--level", "cc2", "-o", (dir / "new.stp").string(), "--html", dir.string()}, "is a directory (--html)"},
  };
  for (const Case& c : cases) {
    const ProgramRun r = run(convert_args(program, c.args));
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_EQ(r.err.rfind("ncbridge: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(listing(dir), (std::vector<std::string>{"a_file", "old.stp"}));
    EXPECT_EQ(slurp(dir / "old.stp"), "old");
  }
}

// An error in the program after outputs were begun: none of them appears, old ones stay.
TEST(ConvertOutputs, ABadProgramLeavesNoOutputAndOldFilesAsTheyWere) {
  const fs::path dir = fresh_directory("bad_program");
  std::string text = slurp(kPlate / "plate.ngc");
  text.insert(text.rfind("M30") == std::string::npos ? text.size() : text.rfind("M30"), "G1 X10 Q&\n");
  put(dir / "bad.ngc", text);
  put(dir / "out.stp", "old stp");
  put(dir / "out.json", "old json");
  for (const std::string level : {"cc1", "cc2"}) {
    const std::vector<std::string> args{"--level", level, "-o", (dir / "out.stp").string(), "--report", (dir / "out.json").string(),
                                        "--html", (dir / "out.html").string()};
    const ProgramRun r = run(convert_args((dir / "bad.ngc").string(), args));
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("ncbridge: error: " + (dir / "bad.ngc").string() + ":"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(dir / "out.stp"), "old stp");
    EXPECT_EQ(slurp(dir / "out.json"), "old json");
    EXPECT_EQ(listing(dir), (std::vector<std::string>{"bad.ngc", "out.json", "out.stp"}));
  }
}

TEST(ConvertOutputs, AFullDeviceFailsTheRunAndTheReportDoesNotAppear) {
  const fs::path dir = fresh_directory("full");
  const ProgramRun r =
      run(convert_args((kPlate / "plate.ngc").string(), {"-o", "/dev/full", "--report", (dir / "r.json").string()}));
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("ncbridge: error: /dev/full: cannot write: No space left on device"), std::string::npos) << r.err;
  EXPECT_TRUE(listing(dir).empty());
}

TEST(ConvertOutputs, AnOutputThatIsAnInputOrTwiceTheSameIsAUsageError) {
  const fs::path dir = fresh_directory("same");
  fs::copy_file(kPlate / "plate.ngc", dir / "plate.ngc");
  const std::string before = slurp(dir / "plate.ngc");
  const ProgramRun over_input = run(convert_args((dir / "plate.ngc").string(), {"-o", (dir / "plate.ngc").string()}));
  EXPECT_EQ(over_input.exit_code, 2) << over_input.err;
  EXPECT_NE(over_input.err.find("is an input of this run"), std::string::npos) << over_input.err;
  EXPECT_EQ(slurp(dir / "plate.ngc"), before);
  const ProgramRun twice = run(convert_args((dir / "plate.ngc").string(),
                                            {"-o", (dir / "a.stp").string(), "--report", (dir / "a.stp").string()}));
  EXPECT_EQ(twice.exit_code, 2) << twice.err;
  EXPECT_NE(twice.err.find("-o and --report name the same output"), std::string::npos) << twice.err;
  EXPECT_EQ(listing(dir), std::vector<std::string>{"plate.ngc"});
}

TEST(Inputs, CanonCheckAndDiffReadStandardInput) {
  const fs::path dir = fresh_directory("stdin");
  const std::string program = (kPlate / "plate.ngc").string();
  const ProgramRun from_file = run({NCBRIDGE_EXECUTABLE, "canon", program, "--tools", (kPlate / "tools.json").string()});
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  const ProgramRun piped = run({NCBRIDGE_EXECUTABLE, "canon", "-", "--tools", (kPlate / "tools.json").string()}, program);
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  EXPECT_EQ(piped.out, from_file.out);
  EXPECT_GT(piped.out.size(), 1000u);

  ASSERT_EQ(run(convert_args(program, {"-o", (dir / "a.stp").string()})).exit_code, 0);
  const ProgramRun check = run({NCBRIDGE_EXECUTABLE, "check", "-"}, dir / "a.stp");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_NE(check.err.find("<stdin>: "), std::string::npos) << check.err;
  const ProgramRun diff = run({NCBRIDGE_EXECUTABLE, "diff", "-", (dir / "a.stp").string()}, dir / "a.stp");
  EXPECT_EQ(diff.exit_code, 0) << diff.out << diff.err;
  const ProgramRun both = run({NCBRIDGE_EXECUTABLE, "diff", "-", "-"}, dir / "a.stp");
  EXPECT_EQ(both.exit_code, 2) << both.err;
}

}  // namespace
}  // namespace ncbridge::cli
