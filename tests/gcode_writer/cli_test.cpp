// `ncbridge gcode` as a user runs it: a written program reads back as the source's motion; a
// refusal, a bad input or an unknown dialect is a located error, a non-zero exit and no file (an
// older file of that name stays as it was).
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include "support/run_program.hpp"
#include "support/same_motion.hpp"

namespace fs = std::filesystem;
using ncbridge::testing::run_program;

namespace {

const fs::path kSource = NCBRIDGE_SOURCE_DIR;
const fs::path kShared = NCBRIDGE_SHARED_DIR;

class GcodeCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ncbridge-gcode-cli-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  static std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  fs::path dir_;
};

TEST_F(GcodeCommand, TranslatesAProgramThatReadsBackAsTheSameMotion) {
  const fs::path plate = kSource / "examples/plate";
  const fs::path out = dir_ / "plate.nc";
  const auto run = run_program({NCBRIDGE_EXECUTABLE, "gcode", (plate / "plate.ngc").string(), "--to", "fanuc", "--tools",
                                (plate / "tools.json").string(), "-o", out.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_TRUE(fs::exists(out));
  EXPECT_NE(read(out).find("O1000 (PLATE)"), std::string::npos);
  const auto source = run_program({NCBRIDGE_EXECUTABLE, "canon", (plate / "plate.ngc").string(), "--tools",
                                   (plate / "tools.json").string()});
  const auto back = run_program({NCBRIDGE_EXECUTABLE, "canon", out.string(), "--dialect", "fanuc", "--tools",
                                 (plate / "tools.json").string()});
  ASSERT_EQ(back.exit_code, 0) << back.err;
  const auto comparison = ncbridge::testing::compare_motion(source.out, back.out);
  EXPECT_TRUE(comparison.equal) << comparison.report;
}

TEST_F(GcodeCommand, ARefusalIsALocatedErrorAndWritesNothing) {
  const fs::path out = dir_ / "pallet.nc";
  std::ofstream(out) << "an older file\n";
  const fs::path program = kSource / "tests/interpreter/golden/programs/m60_pallet_change.ngc";
  const auto run = run_program({NCBRIDGE_EXECUTABLE, "gcode", program.string(), "--to", "fanuc", "-o", out.string()});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("m60_pallet_change.ngc:4"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("fanuc cannot express a pallet change with a stop (M60)"), std::string::npos) << run.err;
  EXPECT_EQ(read(out), "an older file\n");
  for (const auto& entry : fs::directory_iterator(dir_)) EXPECT_EQ(entry.path(), out) << "a temporary file was left";
}

TEST_F(GcodeCommand, ABadProgramIsALocatedErrorAndWritesNothing) {
  const fs::path program = dir_ / "bad.ngc";
  std::ofstream(program) << "G21 G90\nG0 X1\nG1 X2 F100 Q\nM2\n";
  const fs::path out = dir_ / "bad.h";
  const auto run = run_program({NCBRIDGE_EXECUTABLE, "gcode", program.string(), "--dialect", "rs274ngc", "--to",
                                "mach3", "-o", out.string()});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("bad.ngc:3"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(GcodeCommand, PostsACc1FileItConvertedInEveryDialect) {
  const fs::path plate = kSource / "examples/plate";
  const fs::path cc1 = dir_ / "plate_cc1.stp";
  const auto convert = run_program({NCBRIDGE_EXECUTABLE, "convert", (plate / "plate.ngc").string(), "--tools",
                                    (plate / "tools.json").string(), "--stock", (plate / "stock.json").string(),
                                    "--level", "cc1", "-o", cc1.string()});
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  for (const char* to : {"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain"}) {
    const fs::path out = dir_ / (std::string("plate_") + to);
    const auto run = run_program({NCBRIDGE_EXECUTABLE, "gcode", cc1.string(), "--to", to, "-o", out.string()});
    EXPECT_EQ(run.exit_code, 0) << to << ": " << run.err;
    EXPECT_GT(fs::file_size(out), 500u) << to;
  }
}

TEST_F(GcodeCommand, ABrokenCc1FileIsALocatedErrorAndWritesNothing) {
  std::string text = read(fs::path(NCBRIDGE_SHARED_DIR) / "corpus/stepnc/nist_ex1E.stp");
  const std::string toolpath = "#303= TRIMMED_CURVE('path segment1', #306,";
  const auto at = text.find(toolpath);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, toolpath.size(), "#303= TRIMMED_CURVE('path segment1', #99999,");
  const fs::path broken = dir_ / "broken.stp";
  std::ofstream(broken, std::ios::binary) << text;
  const fs::path out = dir_ / "broken.ngc";
  const auto run = run_program({NCBRIDGE_EXECUTABLE, "gcode", broken.string(), "--to", "rs274ngc", "-o", out.string()});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("#99999"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(GcodeCommand, AnUnknownDialectIsRefused) {
  const fs::path out = dir_ / "x.nc";
  const auto run = run_program({NCBRIDGE_EXECUTABLE, "gcode", (kSource / "examples/plate/plate.ngc").string(), "--to",
                                "okuma", "-o", out.string()});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("okuma"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
