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

TEST_F(GcodeCommand, AnUnknownDialectIsRefused) {
  const fs::path out = dir_ / "x.nc";
  const auto run = run_program({NCBRIDGE_EXECUTABLE, "gcode", (kSource / "examples/plate/plate.ngc").string(), "--to",
                                "okuma", "-o", out.string()});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("okuma"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
