// One error style and one set of exit codes in every command (docs/cli.md): every message on
// stderr reads `ncbridge: error: [file:line:col: ]message`, and the status says the kind.
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_program.hpp"

namespace ncbridge::cli {
namespace {

namespace fs = std::filesystem;
using ncbridge::testing::ProgramRun;

const fs::path kPlate = fs::path(NCBRIDGE_SOURCE_DIR) / "examples" / "plate";
const fs::path kShared = NCBRIDGE_SHARED_DIR;
const std::string kSchema = (kShared / "reference" / "iso14649" / "combined_schema_iso14649_only.exp").string();

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = fs::path(NCBRIDGE_BINARY_DIR) / "test_output" / "cli" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

ProgramRun ncbridge(std::vector<std::string> args) {
  args.insert(args.begin(), NCBRIDGE_EXECUTABLE);
  return ncbridge::testing::run_program(args, {{}, {"SOURCE_DATE_EPOCH=1700000000"}, false});
}

// Every line of stderr that is not progress or a summary is an error or warning in the style.
void expect_house_style(const ProgramRun& r) {
  std::istringstream lines(r.err);
  bool any_error = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("ncbridge: error: ", 0) == 0) {
      any_error = true;
      continue;
    }
    EXPECT_EQ(line.rfind("ncbridge: warning: ", 0), 0u) << "not in the house style: " << line;
  }
  EXPECT_TRUE(any_error) << "no `ncbridge: error:` line in:\n" << r.err;
}

struct Expectation {
  std::vector<std::string> args;
  int status;
  std::string message;  // a part of the error line
};

void check(const Expectation& e) {
  const ProgramRun r = ncbridge(e.args);
  std::string command;
  for (const auto& a : e.args) command += a + " ";
  EXPECT_EQ(r.exit_code, e.status) << command << "\n" << r.err;
  expect_house_style(r);
  EXPECT_NE(r.err.find(e.message), std::string::npos) << command << "\nexpected: " << e.message << "\ngot: " << r.err;
}

TEST(CommandLine, UnknownOrMissingCommandsAreUsageErrorsThatListTheCommands) {
  check({{"conver", "x.ngc"}, 2, "unknown command 'conver' (did you mean 'convert'?); the commands are canon, check, convert, diff"});
  check({{"frobnicate"}, 2, "unknown command 'frobnicate'; the commands are"});
  check({{}, 2, "no command given; the commands are canon, check, convert, diff"});
}

TEST(CommandLine, UnknownOptionsNameTheNearestOne) {
  check({{"convert", (kPlate / "plate.ngc").string(), "--outptu", "x.stp"}, 2,
         "convert: unknown option --outptu (did you mean --output?)"});
  check({{"canon", (kPlate / "plate.ngc").string(), "--tool", "t.json"}, 2, "canon: unknown option --tool (did you mean --tools?)"});
  check({{"diff", "a.stp", "b.stp", "--tolerence", "1"}, 2, "diff: unknown option --tolerence (did you mean --tolerance?)"});
  // In a command of a command, the message names both and knows the inner one's options.
#ifdef NCBRIDGE_HAVE_SERVICES
  check({{"capture", "linuxcnc", "--bogus"}, 2, "capture linuxcnc: unknown option --bogus (see ncbridge capture linuxcnc --help)"});
#endif
  // A negative number is a value, not an option.
  const ProgramRun negative = ncbridge({"convert", (kPlate / "plate.ngc").string(), "--tools", (kPlate / "tools.json").string(),
                                        "--stock", (kPlate / "stock.json").string(), "--security-plane", "-5", "-o", "/dev/null"});
  EXPECT_EQ(negative.err.find("unknown option"), std::string::npos) << negative.err;
}

TEST(CommandLine, MissingOrBadValuesAreUsageErrors) {
  const std::string program = (kPlate / "plate.ngc").string();
  check({{"convert", program}, 2, "convert: --output is required (see ncbridge convert --help)"});
  check({{"convert", program, "-o", "x.stp", "--level", "cc3"}, 2, "convert: --level: cc3 not in {cc1,cc2}"});
  check({{"convert", program, "-o", "x.stp"}, 2, "converting a program needs --tools (or --tool-table) and --stock"});
  check({{"diff", "a.stp", "b.stp", "--tolerance", "-1"}, 2, "--tolerance must be a length of 0 or more"});
  check({{"diff", "a.stp", "b.stp", "--tolerance", "nan"}, 2, "--tolerance"});
  check({{"canon", program, "--tools", "a.json", "--tool-table", "b.tbl"}, 2, "give one tool list"});
}

TEST(CommandLine, AMissingInputIsAnInputErrorNamingTheFileInEveryCommand) {
  const std::string missing = (fs::path(NCBRIDGE_BINARY_DIR) / "no_such_file.ngc").string();
  const std::string tools = (kPlate / "tools.json").string(), stock = (kPlate / "stock.json").string();
  check({{"canon", missing}, 1, "ncbridge: error: " + missing + ": no such file (program)"});
  check({{"convert", missing, "--tools", tools, "--stock", stock, "-o", "/dev/null"}, 1,
         "ncbridge: error: " + missing + ": no such file (program)"});
  check({{"convert", (kPlate / "plate.ngc").string(), "--tools", missing, "--stock", stock, "-o", "/dev/null"}, 1,
         "ncbridge: error: " + missing + ": no such file (--tools)"});
  check({{"check", missing}, 1, "ncbridge: error: " + missing + ": no such file (file)"});
  check({{"check", (kPlate / "plate.ngc").string(), "--schema", missing}, 1, missing + ": no such file (--schema)"});
  check({{"diff", missing, missing}, 1, "ncbridge: error: " + missing + ": no such file (first file)"});
  check({{"canon", kPlate.string()}, 1, kPlate.string() + ": is a directory, not a file (program)"});
#ifdef NCBRIDGE_HAVE_SERVICES
  check({{"submit", missing, "--tools", tools, "--stock", stock}, 1, missing + ": no such file (program)"});
  check({{"controller-sim", missing, "--controller", "m1"}, 1, missing + ": no such file (program)"});
#endif
}

TEST(CommandLine, ABadProgramIsALocatedInputError) {
  const fs::path dir = fresh_directory("bad_program_style");
  std::ofstream(dir / "bad.ngc") << "G21 G90\nG0 X0 Y0\nG93.5 X1\nM2\n";
  const std::string bad = (dir / "bad.ngc").string();
  check({{"canon", bad}, 1, "ncbridge: error: " + bad + ":3:1: Unknown g code used: G93.5"});
  check({{"convert", bad, "--tools", (kPlate / "tools.json").string(), "--stock", (kPlate / "stock.json").string(), "-o",
          (dir / "bad.stp").string()},
         1, "ncbridge: error: " + bad + ":3:1: Unknown g code used: G93.5"});
  EXPECT_FALSE(fs::exists(dir / "bad.stp"));
}

TEST(CommandLine, CheckAndDiffStatuses) {
  const fs::path dir = fresh_directory("check_diff_status");
  const std::string broken = (kShared / "corpus" / "part21-negative" / "swapped_refs.stp").string();
  const ProgramRun bad = ncbridge({"check", broken, "--schema", kSchema});
  EXPECT_EQ(bad.exit_code, 1) << bad.err;
  EXPECT_NE(bad.out.find("ncbridge: error: " + broken + ":65: #10 MACHINING_WORKINGSTEP.its_feature"), std::string::npos)
      << bad.out;
  const ProgramRun good = ncbridge({"check", (kShared / "corpus" / "part21-negative" / "ex1_fixed_baseline.stp").string(),
                                    "--schema", kSchema});
  EXPECT_EQ(good.exit_code, 0) << good.out << good.err;

  const std::string tools = (kPlate / "tools.json").string(), stock = (kPlate / "stock.json").string();
  const std::string program = (kPlate / "plate.ngc").string();
  ASSERT_EQ(ncbridge({"convert", program, "--tools", tools, "--stock", stock, "-o", (dir / "a.stp").string()}).exit_code, 0);
  ASSERT_EQ(ncbridge({"convert", program, "--tools", tools, "--stock", stock, "-o", (dir / "b.stp").string(),
                      "--security-plane", "40"}).exit_code, 0);
  EXPECT_EQ(ncbridge({"diff", (dir / "a.stp").string(), (dir / "a.stp").string()}).exit_code, 0);
  const ProgramRun differ = ncbridge({"diff", (dir / "a.stp").string(), (dir / "b.stp").string()});
  EXPECT_EQ(differ.exit_code, 5) << differ.out << differ.err;
  EXPECT_TRUE(differ.err.empty()) << differ.err;  // differences are the result, not an error
  check({{"diff", (dir / "a.stp").string(), program}, 1, "ncbridge: error: " + program + ":1:"});
}

TEST(CommandLine, AnUnwritableOutputIsAnOutputError) {
  check({{"convert", (kPlate / "plate.ngc").string(), "--tools", (kPlate / "tools.json").string(), "--stock",
          (kPlate / "stock.json").string(), "-o", "/no/such/dir/a.stp"},
         3, "ncbridge: error: /no/such/dir/a.stp: the directory /no/such/dir does not exist (-o)"});
}

TEST(CommandLine, HelpAndVersionSucceed) {
  const ProgramRun version = ncbridge({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out.rfind("ncbridge ", 0), 0u) << version.out;
  const ProgramRun help = ncbridge({"convert", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("Exit status: 0 ok, 1 input error, 2 usage error, 3 output error"), std::string::npos) << help.out;
}

#ifdef NCBRIDGE_HAVE_SERVICES
TEST(CommandLine, SubmitWithoutServicesIsServiceUnavailable) {
  // A domain nobody uses, the loopback configuration: nobody answers within --timeout.
  const std::vector<std::string> env{"CYCLONEDDS_URI=file://" NCBRIDGE_SOURCE_DIR "/deploy/cyclonedds/loopback.xml",
                                     "NCBRIDGE_DDS_DOMAIN=" + std::to_string(200 + ::getpid() % 30)};
  const auto r = ncbridge::testing::run_program(
      {NCBRIDGE_EXECUTABLE, "submit", (kPlate / "plate.ngc").string(), "--tools", (kPlate / "tools.json").string(),
       "--stock", (kPlate / "stock.json").string(), "--timeout", "1"},
      {{}, env, false});
  EXPECT_EQ(r.exit_code, 4) << r.err;
  expect_house_style(r);
  EXPECT_NE(r.err.find("no interpreter service on DDS domain"), std::string::npos) << r.err;
  check({{"submit", (kPlate / "plate.ngc").string(), "--tools", (kPlate / "tools.json").string(), "--stock",
          (kPlate / "stock.json").string(), "-o", "x.stp"},
         2, "-o and --output-dir need --wait"});
}
#endif

}  // namespace
}  // namespace ncbridge::cli
