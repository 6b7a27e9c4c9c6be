// CNC programs out through the gcode_writer: the corpus' CNC files in their own dialect (within
// the band at 0.025 and 0.005 mm, at most ArcWelder's motion blocks at 0.025, rs274 running the
// RS274/NGC ones), and a multi-pass program whose passes become the dialect's repeat construct.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/toolpath_optimizer/block_count.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"
#include "ncbridge/toolpath_optimizer/pipeline.hpp"
#include "support.hpp"
#include "support/run_program.hpp"

namespace ncbridge::toolpath_optimizer {
namespace {

namespace fs = std::filesystem;
const fs::path kArcs = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/arcs";

std::map<std::string, std::size_t> arcwelder_blocks_out() {
  std::map<std::string, std::size_t> out;
  std::ifstream in(kArcs / "ANCHOR.md");
  const std::regex row(R"(^\|\s*([A-Za-z0-9_.]+)\s*\|[^|]*\|\s*([0-9,]+)\s*\|)");
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    std::string digits = m[2];
    digits.erase(std::remove(digits.begin(), digits.end(), ','), digits.end());
    out[m[1]] = std::stoul(digits);
  }
  return out;
}

struct Written {
  OptimizeResult result;
  std::string text;
};

Written optimize_cnc(const fs::path& input, interpreter::Dialect in, gcode_writer::Dialect out, double tolerance,
                     bool loops = false) {
  OptimizeRequest request;
  request.input = input;
  request.input_kind = InputKind::Cnc;
  request.cnc.dialect = in;
  request.cnc.require_program_end = false;
  std::vector<setup::Tool> tools(1);
  tools[0].number = tools[0].pocket = 3;  // the HSM program's T3 (lengths do not move the path)
  request.cnc.tools = setup::ToolList(tools);
  request.output = OutputFormat::Cnc;
  request.writer.dialect = out;
  request.writer.tools = request.cnc.tools;
  request.writer.program_name = "OPTIMIZED";
  request.output_name = "optimized" + std::string(gcode_writer::program_extension(out));
  request.optimizer.tolerance_mm = tolerance;
  request.loops = loops;
  Written w;
  OutputSinks sinks;
  sinks.main = [&](std::string_view chunk) { w.text.append(chunk); };
  w.result = optimize(request, sinks);
  return w;
}

// rs274 on a written RS274/NGC program.
void expect_rs274_runs(const std::string& text, const std::string& name) {
  const fs::path path = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()) + ".ngc");
  std::ofstream(path) << text;
  bool installed = false;
  const std::string problems = testing::rs274_problems(path, installed);
  fs::remove(path);
  if (!installed) {
    if (ncbridge::testing::in_ci()) ADD_FAILURE() << "rs274 not installed under CI=true (scripts/install-deps.sh --tests)";
    else std::cout << "SKIPPED rs274 check: rs274 not installed (Debian package linuxcnc-uspace)\n";
    return;
  }
  EXPECT_EQ(problems, "") << name;
}

std::vector<std::string> cnc_files() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(kArcs)) {
    if (entry.path().filename().string().rfind("cnc_", 0) == 0) files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class CncCorpus : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(CncCorpus, OwnDialectWithinTheBandAndAtMostArcWeldersBlocks) {
  const auto& [file, tolerance] = GetParam();
  const auto in = interpreter::detect_dialect_file(kArcs / file).dialect;
  const auto out = *gcode_writer::parse_dialect(interpreter::dialect_name(in));
  const Written w = optimize_cnc(kArcs / file, in, out, tolerance);
  ASSERT_TRUE(w.result.deviation.has_value());
  EXPECT_TRUE(w.result.deviation->passed(tolerance)) << w.result.deviation->largest();
  EXPECT_GT(w.result.deviation->spans, 100u);
  EXPECT_EQ(count_blocks(w.text).motion_blocks, w.result.motion_blocks_out);
  if (tolerance == 0.025) {
    const auto bar = arcwelder_blocks_out();
    ASSERT_TRUE(bar.count(file)) << file << " is not in ANCHOR.md";
    EXPECT_LE(w.result.motion_blocks_out, bar.at(file)) << "ArcWelder left " << bar.at(file);
  }
  if (out == gcode_writer::Dialect::Rs274Ngc) expect_rs274_runs(w.text, file);
  std::cout << file << " @" << tolerance << " as " << gcode_writer::dialect_name(out) << ": " << w.result.motion_blocks_in
            << " -> " << w.result.motion_blocks_out << " motion blocks, " << w.result.stats.arcs << " arcs, largest deviation "
            << w.result.deviation->largest() << "\n";
}

INSTANTIATE_TEST_SUITE_P(Files, CncCorpus,
                         ::testing::Combine(::testing::ValuesIn(cnc_files()), ::testing::Values(0.025, 0.005)),
                         [](const auto& test) {
                           std::string name = std::get<0>(test.param);
                           name = name.substr(0, name.find('.'));
                           return name + (std::get<1>(test.param) == 0.025 ? "_25um" : "_5um");
                         });

// A pocket's finishing passes as a CAM post writes them: at each depth, down, round a polygonal
// circle of 90 segments, back up; 16 depths 0.5 mm apart.
std::string multi_pass_program() {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(4);
  s << "(multi-pass pocket wall, for ncbridge's tests)\nG21 G90 G17 G94\nG0 Z5\nG0 X30 Y0\nF600\n";
  for (int pass = 1; pass <= 16; ++pass) {
    s << "G1 Z" << -0.5 * pass << "\n";
    for (int i = 1; i <= 90; ++i) {
      const double a = 2 * kPi * i / 90;
      s << "G1 X" << 30 * std::cos(a) << " Y" << 30 * std::sin(a) << "\n";
    }
  }
  s << "G0 Z5\nM2\n";
  return s.str();
}

class CncLoops : public ::testing::TestWithParam<gcode_writer::Dialect> {};

TEST_P(CncLoops, PassesBecomeTheDialectsRepeat) {
  const fs::path path = fs::temp_directory_path() / ("passes-" + std::to_string(::getpid()) + ".ngc");
  std::ofstream(path) << multi_pass_program();
  const Written w = optimize_cnc(path, interpreter::Dialect::Rs274Ngc, GetParam(), 0.025, true);
  fs::remove(path);
  ASSERT_TRUE(w.result.deviation.has_value());
  EXPECT_TRUE(w.result.deviation->passed(0.025)) << w.result.deviation->largest()
                                                 << (w.result.deviation->problems.empty() ? "" : " " + w.result.deviation->problems.front());
  EXPECT_EQ(w.result.loops.loops, 1u) << w.text;
  EXPECT_GE(w.result.loops.layers_in_loops, 14u);
  EXPECT_LE(w.result.motion_blocks_out, 12u) << w.text;
  EXPECT_GT(w.result.motion_blocks_in, 1400u);
  if (GetParam() == gcode_writer::Dialect::Rs274Ngc) {
    EXPECT_NE(w.text.find(" repeat ["), std::string::npos) << w.text;
    expect_rs274_runs(w.text, "passes");
  }
  std::cout << gcode_writer::dialect_name(GetParam()) << ": " << w.result.motion_blocks_in << " -> "
            << w.result.motion_blocks_out << " motion blocks\n"
            << w.text;
}

INSTANTIATE_TEST_SUITE_P(Dialects, CncLoops,
                         ::testing::Values(gcode_writer::Dialect::Rs274Ngc, gcode_writer::Dialect::Fanuc,
                                           gcode_writer::Dialect::Mach3, gcode_writer::Dialect::Siemens840D,
                                           gcode_writer::Dialect::Heidenhain),
                         [](const auto& test) { return std::string(gcode_writer::dialect_name(test.param)); });

}  // namespace
}  // namespace ncbridge::toolpath_optimizer

namespace ncbridge::toolpath_optimizer {
namespace {

// A tool change with G43 moves the program frame under the machine: the position after it is
// not where the last move ended. KRL gets there by PTP, and the output reads back within the band.
TEST(CncToKrl, ToolLengthChangeIsReachedByPtp) {
  const fs::path path = fs::temp_directory_path() / ("tools-" + std::to_string(::getpid()) + ".ngc");
  std::ofstream(path) << "G21 G90 G17\nT1 M6\nG43 H1\nG0 X0 Y0 Z10\nG1 Z0 F300\nG1 X10\nG1 X20\nG0 Z10\n"
                         "T2 M6\nG43 H2\nG0 X5 Y5 Z2\nG1 Z-1 F200\nG1 X15\nG0 Z10\nM2\n";
  OptimizeRequest request;
  request.input = path;
  request.input_kind = InputKind::Cnc;
  std::vector<setup::Tool> tools(2);
  tools[0].number = tools[0].pocket = 1;
  tools[0].length = 45;
  tools[1].number = tools[1].pocket = 2;
  tools[1].length = 55;
  request.cnc.tools = setup::ToolList(tools);
  request.output = OutputFormat::Krl;
  request.krl.name = "TOOLS";
  request.output_name = "tools.src";
  std::string src, dat;
  OutputSinks sinks;
  sinks.main = [&](std::string_view chunk) { src.append(chunk); };
  sinks.data = [&](std::string_view chunk) { dat.append(chunk); };
  const OptimizeResult result = optimize(request, sinks);
  fs::remove(path);
  ASSERT_TRUE(result.deviation.has_value());
  EXPECT_TRUE(result.deviation->passed(0.025)) << (result.deviation->problems.empty() ? "" : result.deviation->problems.front());
  // After tool 2's offset the program position Z 10 is Z 0: PTP there, then on.
  EXPECT_NE(src.find("PTP {X 20, Y 0, Z 0,"), std::string::npos) << src;
}

}  // namespace
}  // namespace ncbridge::toolpath_optimizer
