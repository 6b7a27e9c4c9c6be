// The commands on CC2 files: `ncbridge convert CC2 --level cc1` writes explicit toolpaths (a
// CC1 file `ncbridge check` accepts, with every workingstep); `ncbridge gcode CC2 --to DIALECT`
// writes a program, and LinuxCNC's rs274 (the reference interpreter) runs the RS274/NGC one
// without error; bad input leaves no file. A missing rs274 fails under CI=true.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include "ncbridge/step_writer/stepnc_file.hpp"
#include "support/run_program.hpp"

namespace fs = std::filesystem;
using namespace ncbridge;
using ncbridge::testing::run_program;

namespace {

const fs::path kSource = NCBRIDGE_SOURCE_DIR;
const fs::path kNist = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/stepnc/nist_ex1.stp";

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("ncbridge-generator-cli-" + std::to_string(::getpid()) + "-" +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  Scratch() { fs::create_directories(dir / "home"); }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
};

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The example plate converted to CC2 (what `scripts/run-example.sh` makes).
fs::path plate_cc2(const Scratch& s) {
  const fs::path ex = kSource / "examples/plate", out = s.dir / "plate_cc2.stp";
  const auto r = run_program({NCBRIDGE_EXECUTABLE, "convert", (ex / "plate.ngc").string(), "--tools", (ex / "tools.json").string(),
                              "--stock", (ex / "stock.json").string(), "--level", "cc2", "-o", out.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return out;
}

std::size_t workingsteps(const stepnc::Project& p) {
  std::size_t n = 0;
  for (const auto& e : p.main_workplan.its_elements) n += std::holds_alternative<stepnc::MachiningWorkingstep>(e);
  return n;
}

std::size_t toolpath_features(const stepnc::Project& p) {
  std::size_t n = 0;
  for (const auto& f : p.features) n += std::holds_alternative<stepnc::ToolpathFeature>(f);
  return n;
}

void rs274_runs(const Scratch& s, const fs::path& program) {
  const fs::path rs274 = ncbridge::testing::find_on_path("rs274");
  if (rs274.empty()) {
    if (ncbridge::testing::in_ci()) FAIL() << "rs274 not installed under CI=true (scripts/install-deps.sh --tests installs linuxcnc-uspace)";
    GTEST_SKIP() << "SKIPPED: rs274 not installed (Debian package linuxcnc-uspace)";
  }
  // A tool table with every pocket the program may call (T1..T20), rs274's files private.
  const fs::path table = s.dir / "tools.tbl", vars = s.dir / "params.var";
  {
    std::ofstream t(table);
    for (int i = 1; i <= 20; ++i) t << "T" << i << " P" << i << " D10 Z0 ;\n";
  }
  std::ofstream(vars, std::ios::trunc).close();
  ncbridge::testing::RunOptions o;
  o.working_directory = s.dir;
  o.extra_environment = {"HOME=" + (s.dir / "home").string()};
  const auto r = run_program({rs274.string(), "-g", "-n", "2", "-t", table.string(), "-v", vars.string(), program.string()}, o);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.err);
  for (std::string line; std::getline(lines, line);) EXPECT_TRUE(line.empty() || line == "executing") << line;
  // rs274 made the motion: feeds and arcs in its canonical output.
  EXPECT_NE(r.out.find("STRAIGHT_FEED"), std::string::npos);
}

TEST(GeneratorCli, ConvertGivesOurCc2ExplicitToolpaths) {
  Scratch s;
  const fs::path cc2 = plate_cc2(s), cc1 = s.dir / "plate_cc1.stp";
  const auto r = run_program({NCBRIDGE_EXECUTABLE, "convert", cc2.string(), "--level", "cc1", "-o", cc1.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto in = step_writer::read_stepnc_file(cc2).project, out = step_writer::read_stepnc_file(cc1).project;
  EXPECT_EQ(workingsteps(out), workingsteps(in));
  EXPECT_GT(toolpath_features(out), 0u);
  const auto check = run_program({NCBRIDGE_EXECUTABLE, "check", cc1.string()});
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
}

TEST(GeneratorCli, ConvertGivesNistsExampleToolpathsForEveryWorkingstep) {
  Scratch s;
  const fs::path cc1 = s.dir / "ex1_cc1.stp";
  const auto r = run_program({NCBRIDGE_EXECUTABLE, "convert", kNist.string(), "--level", "cc1", "-o", cc1.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto in = step_writer::read_stepnc_file(kNist).project, out = step_writer::read_stepnc_file(cc1).project;
  EXPECT_EQ(workingsteps(out), workingsteps(in));
  EXPECT_NE(r.err.find("no rawpiece"), std::string::npos) << r.err;  // the stock it took is said
}

TEST(GeneratorCli, GcodeWritesOurCc2AsAFanucProgram) {
  Scratch s;
  const fs::path cc2 = plate_cc2(s), nc = s.dir / "part.nc";
  const auto r = run_program({NCBRIDGE_EXECUTABLE, "gcode", cc2.string(), "--to", "fanuc", "--tools",
                              (kSource / "examples/plate/tools.json").string(), "-o", nc.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = read(nc);
  EXPECT_NE(text.find("O1000"), std::string::npos);
  EXPECT_NE(text.find("M30"), std::string::npos);
  EXPECT_NE(text.find("G81"), std::string::npos);  // the drilled holes as cycles
}

TEST(GeneratorCli, GcodeWritesNistsExampleAsRs274ngcThatRs274Runs) {
  Scratch s;
  const fs::path ngc = s.dir / "ex1.ngc";
  const auto r = run_program({NCBRIDGE_EXECUTABLE, "gcode", kNist.string(), "--to", "rs274ngc", "-o", ngc.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  rs274_runs(s, ngc);
}

TEST(GeneratorCli, GcodeWritesOurCc2AsRs274ngcThatRs274Runs) {
  Scratch s;
  const fs::path cc2 = plate_cc2(s), ngc = s.dir / "plate.ngc";
  const auto r = run_program({NCBRIDGE_EXECUTABLE, "gcode", cc2.string(), "--to", "rs274ngc", "-o", ngc.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  rs274_runs(s, ngc);
}

TEST(GeneratorCli, ACc2ThatCannotBeCutLeavesNoFile) {
  Scratch s;
  // NIST's example with its end mill made 500 mm wide: no pocket takes it.
  std::string text = read(kNist);
  const std::string mill = "#30= MILLING_TOOL_DIMENSION(18.000,";
  const auto at = text.find(mill);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, mill.size(), "#30= MILLING_TOOL_DIMENSION(500.000,");
  const fs::path broken = s.dir / "broken.stp", out = s.dir / "out.stp", nc = s.dir / "out.nc";
  std::ofstream(broken, std::ios::binary) << text;
  const auto c = run_program({NCBRIDGE_EXECUTABLE, "convert", broken.string(), "--level", "cc1", "-o", out.string()});
  EXPECT_NE(c.exit_code, 0);
  EXPECT_NE(c.err.find("broken.stp"), std::string::npos) << c.err;
  EXPECT_NE(c.err.find("workingstep"), std::string::npos) << c.err;
  EXPECT_FALSE(fs::exists(out));
  const auto g = run_program({NCBRIDGE_EXECUTABLE, "gcode", broken.string(), "--to", "rs274ngc", "-o", nc.string()});
  EXPECT_NE(g.exit_code, 0);
  EXPECT_NE(g.err.find("workingstep"), std::string::npos) << g.err;
  EXPECT_FALSE(fs::exists(nc));
}

}  // namespace
