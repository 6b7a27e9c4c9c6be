// `ncbridge optimize` as a user runs it: the output and the report, the summary on stderr, and
// bad input refused with a located error and no output file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support.hpp"
#include "support/run_program.hpp"

namespace ncbridge::toolpath_optimizer {
namespace {

namespace fs = std::filesystem;
using ncbridge::testing::run_program;

class OptimizeCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ncbridge-optimize-cli-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  fs::path dir_;
};

const std::string kCylinder = std::string(NCBRIDGE_SHARED_DIR) + "/corpus/arcs/slic3r129_cylinder.gcode";

TEST_F(OptimizeCli, WritesTheProgramAndTheReport) {
  const auto out = dir_ / "cylinder_arcs.gcode", report = dir_ / "opt.json";
  const auto run = run_program({NCBRIDGE_EXECUTABLE, "optimize", kCylinder, "--flavor", "marlin", "--tolerance", "0.025",
                                "-o", out.string(), "--report", report.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("optimize: 16169 -> "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("largest deviation"), std::string::npos);
  const auto j = nlohmann::json::parse(testing::read_file(report));
  EXPECT_EQ(j["input_counts"]["motion_blocks"], 16169);
  EXPECT_EQ(j["output_counts"]["motion_blocks"].get<std::size_t>(), testing::count_motion_blocks(testing::read_file(out)));
  EXPECT_GT(j["made"]["arcs"].get<int>(), 100);
  EXPECT_TRUE(j["deviation"]["checked"].get<bool>());
  EXPECT_LE(j["deviation"]["largest_mm"].get<double>(), 0.025 + 1e-6);
  EXPECT_GT(j["time_ms"]["total"].get<double>(), 0);
}

TEST_F(OptimizeCli, KrlOutputIsASrcAndItsDat) {
  const auto src = dir_ / "cylinder.src";
  const auto run = run_program({NCBRIDGE_EXECUTABLE, "optimize", kCylinder, "--flavor", "marlin", "--to", "krl", "--loops",
                                "-o", src.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string text = testing::read_file(src), dat = testing::read_file(dir_ / "cylinder.dat");
  EXPECT_NE(text.find("DEF CYLINDER( )"), std::string::npos);
  EXPECT_NE(text.find("FOR NCB_LAYER = 1 TO "), std::string::npos);
  EXPECT_NE(dat.find("DEFDAT CYLINDER PUBLIC"), std::string::npos);
  EXPECT_NE(run.err.find(" loops, largest deviation"), std::string::npos) << run.err;
  // Not a .src: refused, neither file written.
  const auto bad = run_program({NCBRIDGE_EXECUTABLE, "optimize", kCylinder, "--flavor", "marlin", "--to", "krl",
                                "-o", (dir_ / "other.krl").string()});
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("KRL output is a .src file"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "other.krl"));
  EXPECT_FALSE(fs::exists(dir_ / "other.dat"));
}

TEST_F(OptimizeCli, BadArgumentsAndBadInputLeaveNoOutput) {
  const auto good = write("part.gcode", "G1 X0 Y0 F1800\nG1 X1 Y0 E0.1\nG1 X2 Y0 E0.2\n");
  const auto bad = write("bad.gcode", "G28\nG1 X0 Y0\nG1 X1.2.3 Y4 E1\n");
  const auto out = dir_ / "out.gcode";
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"optimize", good.string(), "--flavor", "prusa", "-o", out.string()}, "unknown --flavor \"prusa\""},
      {{"optimize", good.string(), "--flavor", "marlin", "--tolerance", "0", "-o", out.string()}, "--tolerance must be greater than 0"},
      {{"optimize", good.string(), "--flavor", "marlin", "--tolerance", "-0.1", "-o", out.string()}, "--tolerance must be greater than 0"},
      {{"optimize", bad.string(), "--flavor", "marlin", "-o", out.string()}, bad.string() + ":3:4: error: X word without a valid number"},
      {{"optimize", good.string(), "--flavor", "marlin", "--loops", "-o", out.string()}, "printer G-code has no loop construct"},
      {{"optimize", good.string(), "--flavor", "marlin", "--to", "heidenhain-ish", "-o", out.string()}, "unknown --to"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> argv = {NCBRIDGE_EXECUTABLE};
    argv.insert(argv.end(), c.args.begin(), c.args.end());
    const auto run = run_program(argv);
    EXPECT_NE(run.exit_code, 0) << c.message;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out)) << c.message;
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 2) << "a temporary file was left";
  }
}

}  // namespace
}  // namespace ncbridge::toolpath_optimizer
