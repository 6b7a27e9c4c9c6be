// `ncbridge convert --level cc1` streams the Part 21 file and the --report JSON element by
// element: the report must still describe the whole workplan as the model has it, and a failed
// run must leave neither file behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "support/run_program.hpp"

namespace ncbridge::cc1_builder::testing {
namespace {

namespace fs = std::filesystem;
const fs::path kShared = NCBRIDGE_SHARED_DIR;

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = fs::path(NCBRIDGE_BINARY_DIR) / "test_output" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ConvertReport, StreamedReportDescribesTheWholeWorkplan) {
  const fs::path part = kShared / "corpus/cam/p03_bracket_steps";
  const fs::path program = fs::exists(part / "part.linuxcnc.ngc") ? part / "part.linuxcnc.ngc" : part / "part.nc";
  const fs::path dir = fresh_directory("convert_report");
  const auto run = ncbridge::testing::run_program(
      {NCBRIDGE_EXECUTABLE, "convert", program.string(), "--tools", (part / "tools.json").string(), "--stock",
       (part / "stock.json").string(), "-o", (dir / "p03.stp").string(), "--report", (dir / "p03.json").string()},
      {{}, {"SOURCE_DATE_EPOCH=1700000000"}, false});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(slurp(dir / "p03.json"));

  // The same conversion in process, whole.
  Options o;
  o.tools = setup::read_tool_list(part / "tools.json");
  o.stock = setup::read_stock(part / "stock.json");
  interpreter::Options io;
  io.tools = o.tools;
  Cc1Builder builder(o);
  interpreter::interpret_file(program, io, builder);
  const stepnc::Project p = builder.take_project();

  EXPECT_EQ(report.at("level"), "cc1");
  EXPECT_EQ(report.at("canonical_calls").get<std::uint64_t>(), builder.calls_seen());
  EXPECT_EQ(report.at("output_bytes").get<std::uint64_t>(), fs::file_size(dir / "p03.stp"));
  const auto& steps = report.at("workingsteps");
  ASSERT_EQ(steps.size(), p.main_workplan.its_elements.size());
  std::size_t machining = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    SCOPED_TRACE(i);
    const auto& e = p.main_workplan.its_elements[i];
    std::visit([&](const auto& x) {
      EXPECT_EQ(steps[i].at("id"), x.its_id);
      if (x.source.first_line != 0) {
        EXPECT_EQ(steps[i].at("lines"), nlohmann::json::array({x.source.first_line, x.source.last_line}));
      } else {
        EXPECT_FALSE(steps[i].contains("lines"));
      }
    }, e);
    if (const auto* ws = std::get_if<stepnc::MachiningWorkingstep>(&e)) {
      ++machining;
      const auto& op = p.operation(ws->its_operation);
      EXPECT_EQ(steps[i].at("kind"), "MACHINING_WORKINGSTEP");
      EXPECT_EQ(steps[i].at("operation"), std::string(stepnc::entity_name(op)));
      EXPECT_EQ(steps[i].at("feature"), stepnc::feature_id(p.feature(ws->its_feature)));
      const auto& mop = stepnc::machining_operation(op);
      EXPECT_EQ(steps[i].at("tool"), p.tool(mop.its_tool).its_id);
      const auto& t = p.technology(mop.its_technology);
      if (t.feedrate) {
        EXPECT_DOUBLE_EQ(steps[i].at("feedrate_m_per_s").get<double>(), *t.feedrate);
      }
      if (t.spindle) {
        EXPECT_DOUBLE_EQ(steps[i].at("spindle_rev_per_s").get<double>(), *t.spindle);
      }
    } else {
      EXPECT_EQ(steps[i].at("kind"), "RAPID_MOVEMENT");
    }
  }
  EXPECT_GT(machining, 5u);
  ASSERT_EQ(report.at("features").size(), p.features.size());
  for (std::size_t i = 0; i < p.features.size(); ++i) {
    EXPECT_EQ(report["features"][i].at("id"), stepnc::feature_id(p.features[i]));
    EXPECT_EQ(report["features"][i].at("type"), std::string(stepnc::entity_name(p.features[i])));
  }
  ASSERT_EQ(report.at("tools").size(), p.tools.size());
  EXPECT_EQ(report["tools"][0].at("id"), p.tools[0].its_id);
  for (const char* stage : {"interpreter", "cc1_builder", "step_writer", "output", "total"}) {
    EXPECT_TRUE(report.at("timings_ms").contains(stage)) << stage;
  }

  // The streamed file is the whole model's file.
  step_writer::StepncWriteOptions w;
  w.file_name = "p03.stp";
  w.unix_time = 1700000000;
  EXPECT_TRUE(slurp(dir / "p03.stp") == step_writer::write_stepnc(p, w));
}

TEST(ConvertReport, AFailedStreamedRunLeavesNoFileBehind) {
  const fs::path paper = kShared / "corpus/paper";
  const fs::path dir = fresh_directory("convert_report_failed");
  std::ofstream(dir / "tools.json") << R"([{"number": 7, "type": "drill", "diameter": 5, "length": 50}])";
  const auto run = ncbridge::testing::run_program(
      {NCBRIDGE_EXECUTABLE, "convert", (paper / "face_mill.ngc").string(), "--tools", (dir / "tools.json").string(),
       "--stock", (paper / "stock.json").string(), "-o", (dir / "out.stp").string(), "--report", (dir / "out.json").string()});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("face_mill.ngc:"), std::string::npos) << run.err;
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& f : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);  // tools.json only: no output, no report, no temporary
}

}  // namespace
}  // namespace ncbridge::cc1_builder::testing
