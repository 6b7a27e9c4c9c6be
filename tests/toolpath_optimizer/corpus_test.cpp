// Every file of ../shared/corpus/arcs/ at 0.025 and 0.005 mm: the output stays in the band as
// the deviation checker reads it back (both ways, per layer, extrusion per segment), every
// line that is not a motion comes through in order, and at 0.025 mm no file has more motion
// blocks than ArcWelder left in it (the table in ANCHOR.md is the bar, read from there).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <unistd.h>

#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/toolpath_optimizer/pipeline.hpp"
#include "support.hpp"

namespace ncbridge::toolpath_optimizer {
namespace {

namespace fs = std::filesystem;
const fs::path kArcs = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/arcs";

// ANCHOR.md: | file | G0+G1 in | motion out (default) | reduction | with travel + 3D arcs | MB/s |
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

std::vector<std::string> printer_files() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(kArcs)) {
    if (entry.path().extension() == ".gcode") files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The lines that are not motions, in order (comments and blank lines included).
std::vector<std::string> other_lines(const std::string& text) {
  std::vector<std::string> out;
  struct Sink final : ElementSink {
    std::vector<std::string>* out;
    void element(Element&& e) override {
      if (auto* t = std::get_if<TextLine>(&e.item)) out->push_back(t->text);
    }
  } sink;
  sink.out = &out;
  read_printer_text(text, "x", PrinterFlavor::Marlin, sink);
  return out;
}

class ArcsCorpus : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(ArcsCorpus, WithinTheBandAndAtMostArcWeldersBlocks) {
  const auto& [file, tolerance] = GetParam();
  OptimizeRequest request;
  request.input = kArcs / file;
  request.output_name = file;
  request.optimizer.tolerance_mm = tolerance;
  std::string output;
  OutputSinks sinks;
  sinks.main = [&](std::string_view chunk) { output.append(chunk); };
  const OptimizeResult result = optimize(request, sinks);
  ASSERT_TRUE(result.deviation.has_value());
  const DeviationReport& d = *result.deviation;
  EXPECT_TRUE(d.passed(tolerance)) << d.largest() << (d.problems.empty() ? "" : " " + d.problems.front());
  EXPECT_LE(d.largest(), tolerance + 1e-6);
  EXPECT_LT(d.extrusion_error, 1e-6);
  EXPECT_GT(d.spans, 1000u);

  const std::string input = testing::read_file(request.input);
  EXPECT_EQ(testing::count_motion_blocks(input), result.motion_blocks_in);
  EXPECT_EQ(testing::count_motion_blocks(output), result.motion_blocks_out);
  EXPECT_EQ(other_lines(output), other_lines(input));
  if (tolerance == 0.025) {
    const auto bar = arcwelder_blocks_out();
    ASSERT_TRUE(bar.count(file)) << file << " is not in ANCHOR.md";
    EXPECT_LE(result.motion_blocks_out, bar.at(file)) << "ArcWelder left " << bar.at(file);
  }
  std::cout << file << " @" << tolerance << ": " << result.motion_blocks_in << " -> " << result.motion_blocks_out
            << " motion blocks, " << result.stats.arcs << " arcs, largest deviation " << d.largest() << "\n";
}

// The checker streams printer output: it holds the input the output has not yet caught up with,
// not the file, so four copies of a file in one are checked holding as much as one copy.
TEST(ArcsCorpusMemory, TheCheckHoldsAsMuchForFourCopiesAsForOne) {
  const fs::path scratch = fs::temp_directory_path() / ("ncbridge-optimize-memory-" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  const std::string one = testing::read_file(kArcs / "slic3r129_cylinder.gcode");
  std::size_t held[2] = {0, 0};
  for (int copies : {1, 4}) {
    const fs::path file = scratch / ("copies" + std::to_string(copies) + ".gcode");
    {
      std::ofstream out(file, std::ios::binary);
      for (int i = 0; i < copies; ++i) out << one;
    }
    OptimizeRequest request;
    request.input = file;
    request.output_name = file.filename().string();
    std::size_t written = 0;
    OutputSinks sinks;
    sinks.main = [&](std::string_view chunk) { written += chunk.size(); };
    const OptimizeResult result = optimize(request, sinks);
    ASSERT_TRUE(result.deviation.has_value());
    EXPECT_TRUE(result.deviation->passed(0.025)) << result.deviation->largest();
    EXPECT_EQ(result.deviation->input_motions, copies * (result.deviation->input_motions / copies));
    held[copies == 1 ? 0 : 1] = result.check_pieces_held;
    std::cout << copies << " copies: " << result.deviation->input_motions << " input pieces, at most "
              << result.check_pieces_held << " held\n";
  }
  fs::remove_all(scratch);
  EXPECT_GT(held[0], 0u);
  EXPECT_LE(held[1], held[0] + held[0] / 10);
  EXPECT_LT(held[0], 5000u);  // the file has 16,169 motions; what is held is a run and 8 KiB of output
}

// The same files to KUKA KRL with loops: the .src read back by the KRL reader stays in the band.
class ArcsCorpusKrl : public ::testing::TestWithParam<std::string> {};

TEST_P(ArcsCorpusKrl, ReadsBackWithinTheBand) {
  OptimizeRequest request;
  request.input = kArcs / GetParam();
  request.output_name = GetParam() + ".src";
  request.output = OutputFormat::Krl;
  request.loops = true;
  std::string src, dat;
  OutputSinks sinks;
  sinks.main = [&](std::string_view chunk) { src.append(chunk); };
  sinks.data = [&](std::string_view chunk) { dat.append(chunk); };
  const OptimizeResult result = optimize(request, sinks);
  ASSERT_TRUE(result.deviation.has_value());
  EXPECT_TRUE(result.deviation->passed(0.025)) << result.deviation->largest();
  EXPECT_LT(result.deviation->extrusion_error, 1e-4);
  EXPECT_LE(result.motion_blocks_out, result.motion_blocks_in + 2);  // PTP home at both ends
  EXPECT_NE(dat.find("ENDDAT"), std::string::npos);
  std::cout << GetParam() << " to KRL: " << result.motion_blocks_in << " -> " << result.motion_blocks_out
            << " motion statements, " << result.loops.loops << " loops\n";
}

// The CNC files of the corpus, read through the interpreter (dialect detected), to KRL.
std::vector<std::string> cnc_files() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(kArcs)) {
    if (entry.path().filename().string().rfind("cnc_", 0) == 0) files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class CncCorpusKrl : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(CncCorpusKrl, ReadsBackWithinTheBand) {
  const auto& [file, tolerance] = GetParam();
  OptimizeRequest request;
  request.input = kArcs / file;
  request.input_kind = InputKind::Cnc;
  request.cnc.dialect = interpreter::detect_dialect_file(request.input).dialect;
  request.cnc.require_program_end = false;
  std::vector<setup::Tool> tools(1);
  tools[0].number = tools[0].pocket = 3;  // the HSM program's T3 (lengths do not move the path)
  request.cnc.tools = setup::ToolList(tools);
  request.output_name = file + ".src";
  request.output = OutputFormat::Krl;
  request.optimizer.tolerance_mm = tolerance;
  std::string src, dat;
  OutputSinks sinks;
  sinks.main = [&](std::string_view chunk) { src.append(chunk); };
  sinks.data = [&](std::string_view chunk) { dat.append(chunk); };
  const OptimizeResult result = optimize(request, sinks);
  ASSERT_TRUE(result.deviation.has_value());
  EXPECT_TRUE(result.deviation->passed(tolerance)) << result.deviation->largest();
  EXPECT_GT(result.deviation->spans, 100u);
  EXPECT_LT(result.motion_blocks_out, result.motion_blocks_in);
  std::cout << file << " @" << tolerance << " to KRL: " << result.motion_blocks_in << " -> " << result.motion_blocks_out
            << " motion statements, " << result.stats.arcs << " arcs, largest deviation " << result.deviation->largest() << "\n";
}

INSTANTIATE_TEST_SUITE_P(Files, CncCorpusKrl,
                         ::testing::Combine(::testing::ValuesIn(cnc_files()), ::testing::Values(0.025, 0.005)),
                         [](const auto& test) {
                           std::string name = std::get<0>(test.param);
                           name = name.substr(0, name.find('.'));
                           return name + (std::get<1>(test.param) == 0.025 ? "_25um" : "_5um");
                         });

INSTANTIATE_TEST_SUITE_P(Files, ArcsCorpusKrl, ::testing::ValuesIn(printer_files()), [](const auto& test) {
  return test.param.substr(0, test.param.find('.'));
});

INSTANTIATE_TEST_SUITE_P(Files, ArcsCorpus,
                         ::testing::Combine(::testing::ValuesIn(printer_files()), ::testing::Values(0.025, 0.005)),
                         [](const auto& test) {
                           std::string name = std::get<0>(test.param);
                           name = name.substr(0, name.find('.'));
                           return name + (std::get<1>(test.param) == 0.025 ? "_25um" : "_5um");
                         });

}  // namespace
}  // namespace ncbridge::toolpath_optimizer
