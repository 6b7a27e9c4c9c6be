// The real programs of shared/corpus/realworld (read in place, never copied): each converts to
// CC2 with its tools and stock, or stops where and why this file says (the reasons are in
// docs/recognition.md). The RS274/NGC programs also move the tool exactly as LinuxCNC's rs274
// does with the same tool lengths.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "motion_path.hpp"
#include "support/run_program.hpp"

namespace fs = std::filesystem;
using ncbridge::testing::compare_tool_paths;
using ncbridge::testing::run_program;
using ncbridge::testing::tool_path;

namespace {

const fs::path kRealWorld = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/realworld";

struct RealProgram {
  std::string path;      // under corpus/realworld
  std::string dialect;
  std::string stop;      // empty: converts; else "line:column" where it stops
  std::string because;   // a fragment of the message it stops with
};

// BOTTLE.NC writes arc centres as absolute coordinates: a Fanuc control stops there too (alarm
// PS0020). 123.mpf turns the working plane for an angle head (ROT Y-90): not three-axis milling.
const std::vector<RealProgram> kPrograms = {
    {"fanuc/BOTTLE.NC", "fanuc", "12:23", "Radius to end of arc differs from radius to start"},
    {"fanuc/FANUC0M.nc", "fanuc", "", ""},
    {"fanuc/G83.NC", "fanuc", "", ""},
    {"fanuc/PROGRAM2.NC", "fanuc", "", ""},
    {"heidenhain/668.klartext", "heidenhain", "", ""},
    {"heidenhain/Krivka.klartext", "heidenhain", "", ""},
    {"heidenhain/SLII001.klartext", "heidenhain", "", ""},
    {"heidenhain/VESELYparametr.klartext", "heidenhain", "", ""},
    {"heidenhain/programm-zirkularnut-fraesen.klartext", "heidenhain", "", ""},
    {"mach3/bear.nc", "mach3", "", ""},
    {"mach3/botomata_bottom.nc", "mach3", "", ""},
    {"mach3/scorpion.nc", "mach3", "", ""},
    {"rs274ngc/genes-encoder.ngc", "rs274ngc", "", ""},
    {"rs274ngc/heart.ngc", "rs274ngc", "", ""},
    {"rs274ngc/probe_round_pocket.ngc", "rs274ngc", "", ""},
    {"siemens840d/123.mpf", "siemens840d", "17:5", "ROT Y"},
    {"siemens840d/kanavka_vint_sector.mpf", "siemens840d", "", ""},
};

fs::path beside(const fs::path& program, const std::string& suffix) {
  return program.parent_path() / (program.stem().string() + suffix);
}

std::vector<std::string> subroutine_path(const fs::path& program) {
  const fs::path sub = program.parent_path() / ("sub_" + program.stem().string());
  if (!fs::exists(sub)) return {};
  return {"--subroutine-path", sub.string()};
}

class RealWorld : public ::testing::TestWithParam<RealProgram> {};

TEST_P(RealWorld, ConvertsOrStopsWhereItsReasonSays) {
  const RealProgram& p = GetParam();
  const fs::path program = kRealWorld / p.path;
  ASSERT_TRUE(fs::exists(program)) << program;
  const fs::path out = fs::temp_directory_path() / ("ncbridge_realworld_" + std::to_string(::getpid()) + ".stp");
  std::vector<std::string> argv = {NCBRIDGE_EXECUTABLE, "convert", program.string(), "--dialect", p.dialect,
                                   "--tools", beside(program, ".tools.json").string(), "--stock",
                                   beside(program, ".stock.json").string(), "--level", "cc2", "-o", out.string()};
  const auto sub = subroutine_path(program);
  argv.insert(argv.end(), sub.begin(), sub.end());
  const auto run = run_program(argv);
  if (p.stop.empty()) {
    EXPECT_EQ(run.exit_code, 0) << p.path << ": " << run.err;
    EXPECT_TRUE(fs::exists(out)) << p.path;
  } else {
    EXPECT_NE(run.exit_code, 0) << p.path;
    EXPECT_NE(run.err.find("ncbridge: error: " + program.string() + ":" + p.stop + ": "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(p.because), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out)) << "nothing half-written";
  }
  std::error_code ignored;
  fs::remove(out, ignored);
}

INSTANTIATE_TEST_SUITE_P(Corpus, RealWorld, ::testing::ValuesIn(kPrograms),
                         [](const ::testing::TestParamInfo<RealProgram>& info) {
                           std::string name = info.param.path;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

// The tool list as a LinuxCNC tool table (inches, rs274's machine unit).
void write_tool_table(const fs::path& tools_json, const fs::path& table) {
  std::ifstream in(tools_json);
  const auto tools = nlohmann::json::parse(in);
  std::ofstream out(table);
  for (const auto& t : tools) {
    const int n = t.at("number").get<int>();
    out << "T" << n << " P" << n << " D" << t.at("diameter").get<double>() / 25.4 << " Z"
        << t.value("length", 0.0) / 25.4 << "\n";
  }
}

TEST(RealWorld, Rs274NgcProgramsMoveAsRs274Does) {
  const fs::path rs274 = ncbridge::testing::find_on_path("rs274");
  if (rs274.empty()) {
    if (ncbridge::testing::in_ci()) FAIL() << "rs274 not installed under CI=true (scripts/install-deps.sh --tests installs linuxcnc-uspace)";
    GTEST_SKIP() << "SKIPPED: rs274 not installed (Debian package linuxcnc-uspace)";
  }
  const fs::path scratch = fs::temp_directory_path() / ("ncbridge_realworld_rs274_" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  int compared = 0;
  std::size_t moves = 0;
  for (const RealProgram& p : kPrograms) {
    if (p.dialect != "rs274ngc") continue;
    const fs::path program = kRealWorld / p.path;
    const fs::path table = scratch / "tools.tbl";
    write_tool_table(beside(program, ".tools.json"), table);
    ncbridge::testing::RunOptions options;
    options.working_directory = program.parent_path();
    options.extra_environment = {"HOME=" + scratch.string()};
    const fs::path params = scratch / "params.var";
    std::ofstream(params).close();
    const auto reference = run_program({rs274.string(), "-g", "-t", table.string(), "-v", params.string(),
                                        program.string()}, options);
    std::vector<std::string> argv = {NCBRIDGE_EXECUTABLE, "canon", program.string(), "--tools",
                                     beside(program, ".tools.json").string()};
    const auto sub = subroutine_path(program);
    argv.insert(argv.end(), sub.begin(), sub.end());
    const auto ours = run_program(argv, options);
    // heart.ngc ends without M2 or %: both stop there with LinuxCNC's error, after every move
    EXPECT_EQ(reference.exit_code != 0, ours.exit_code != 0) << p.path << "\nrs274: " << reference.err << "\nncbridge: " << ours.err;
    // probe_round_pocket.ngc only defines its subroutine: neither moves
    const auto expected = tool_path(reference.out);
    moves += expected.size();
    // one unit of the last printed digit (%.4f): an inch program's last digit may round either way
    const auto comparison = compare_tool_paths(expected, tool_path(ours.out), 2e-4);
    EXPECT_TRUE(comparison.equal) << p.path << ": " << comparison.report;
    ++compared;
  }
  std::error_code ignored;
  fs::remove_all(scratch, ignored);
  EXPECT_EQ(compared, 3);
  EXPECT_GT(moves, 1000u);
}

}  // namespace
