// Streamed CC1 (the builder hands each finished workplan element to the Part 21 writer, nothing
// of the workplan is kept) gives the same bytes as building the whole project and writing it,
// on the corpus programs and the interpreter's golden programs.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "support/golden_cases.hpp"
#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/step_writer/stepnc_stream_writer.hpp"

namespace ncbridge::cc1_builder::testing {
namespace {

namespace fs = std::filesystem;
const fs::path kShared = NCBRIDGE_SHARED_DIR;
const fs::path kSource = NCBRIDGE_SOURCE_DIR;

struct Input {
  std::string name;
  fs::path program;
  setup::ToolList tools;
  std::optional<setup::Stock> stock;
  std::vector<fs::path> subroutine_path;
};

step_writer::StepncWriteOptions write_options() {
  step_writer::StepncWriteOptions w;
  w.file_name = "cc1.stp";
  w.unix_time = 1700000000;
  return w;
}

Options builder_options(const Input& in) {
  Options o;
  o.tools = in.tools;
  o.stock = in.stock;
  return o;
}

void interpret(const Input& in, canonical::Sink& sink) {
  interpreter::Options io;
  io.tools = in.tools;
  io.subroutine_path = in.subroutine_path;
  interpreter::interpret_file(in.program, io, sink);
}

struct Written {
  std::string text;
  std::string error;  // the InputError's message when the program cannot be converted
  std::size_t elements = 0;
};

Written whole(const Input& in) {
  Written w;
  try {
    Cc1Builder builder(builder_options(in));
    interpret(in, builder);
    const stepnc::Project project = builder.take_project();
    w.elements = project.main_workplan.its_elements.size();
    w.text = step_writer::write_stepnc(project, write_options());
  } catch (const InputError& e) {
    w.error = e.what();
  }
  return w;
}

// Counts what the builder hands over and checks it is complete when handed over.
class CheckingWriter final : public WorkplanSink {
 public:
  explicit CheckingWriter(step_writer::StepncStreamWriter& writer) : writer_(writer) {}
  void element(const stepnc::Project& project, const stepnc::Executable& e) override {
    if (const auto* ws = std::get_if<stepnc::MachiningWorkingstep>(&e)) {
      EXPECT_LT(ws->its_feature.index, project.features.size());
      EXPECT_LT(ws->its_operation.index, project.operations.size());
      EXPECT_LE(project.features.size(), 1u);  // only the element's own
    }
    EXPECT_TRUE(project.main_workplan.its_elements.empty());
    writer_.element(project, e);
    ++count;
  }
  std::size_t count = 0;

 private:
  step_writer::StepncStreamWriter& writer_;
};

Written streamed(const Input& in) {
  Written w;
  try {
    step_writer::StepncStreamWriter writer(write_options(), [&](std::string_view chunk) { w.text += chunk; });
    CheckingWriter elements(writer);
    Cc1Builder builder(builder_options(in), &elements);
    interpret(in, builder);
    const stepnc::Project project = builder.take_project();
    EXPECT_TRUE(project.main_workplan.its_elements.empty());
    EXPECT_TRUE(project.features.empty());
    EXPECT_TRUE(project.operations.empty());
    writer.finish(project);
    w.elements = elements.count;
  } catch (const InputError& e) {
    w = Written{};
    w.error = e.what();
  }
  return w;
}

std::vector<Input> corpus_inputs() {
  std::vector<Input> inputs;
  const fs::path paper = kShared / "corpus/paper";
  for (const char* name : {"face_mill.ngc", "test_part.ngc"}) {
    inputs.push_back({name, paper / name, setup::read_tool_list(paper / "tools.json"), setup::read_stock(paper / "stock.json"), {}});
  }
  std::vector<fs::path> parts;
  for (const auto& d : fs::directory_iterator(kShared / "corpus/cam")) parts.push_back(d.path());
  std::sort(parts.begin(), parts.end());
  for (const auto& d : parts) {
    const fs::path program = fs::exists(d / "part.linuxcnc.ngc") ? d / "part.linuxcnc.ngc" : d / "part.nc";
    inputs.push_back({d.filename().string(), program, setup::read_tool_list(d / "tools.json"), setup::read_stock(d / "stock.json"), {}});
  }
  return inputs;
}

std::vector<Input> golden_inputs() {
  std::vector<Input> inputs;
  for (const auto& c : ncbridge::testing::read_golden_cases(kSource / "tests/interpreter/golden", kShared)) {
    Input in{c.name, c.program, {}, std::nullopt, {}};
    if (c.tools_kind == "tools-json") {
      in.tools = setup::read_tool_list(c.tools_file);
    } else {
      in.tools = setup::read_linuxcnc_tool_table(
          c.tools_file, c.tools_kind == "tool-table-inch" ? setup::LengthUnits::Inches : setup::LengthUnits::Millimeters);
    }
    if (!c.subroutine_path.empty()) in.subroutine_path.push_back(c.subroutine_path);
    inputs.push_back(std::move(in));
  }
  return inputs;
}

void expect_same_bytes(const std::vector<Input>& inputs, std::size_t* converted) {
  for (const auto& in : inputs) {
    SCOPED_TRACE(in.name);
    const Written a = whole(in);
    const Written b = streamed(in);
    EXPECT_EQ(a.error, b.error);
    EXPECT_EQ(a.elements, b.elements);
    EXPECT_TRUE(a.text == b.text) << "the streamed file differs (sizes " << a.text.size() << " and " << b.text.size() << ")";
    if (a.error.empty() && a.elements > 0) ++*converted;
  }
}

TEST(StreamedCc1, CorpusProgramsGiveTheBytesOfTheWholeProject) {
  const auto inputs = corpus_inputs();
  ASSERT_EQ(inputs.size(), 7u);
  std::size_t converted = 0;
  expect_same_bytes(inputs, &converted);
  EXPECT_EQ(converted, inputs.size());
}

TEST(StreamedCc1, GoldenProgramsGiveTheBytesOfTheWholeProject) {
  const auto inputs = golden_inputs();
  ASSERT_GT(inputs.size(), 50u);
  std::size_t converted = 0;
  expect_same_bytes(inputs, &converted);
  EXPECT_GT(converted, inputs.size() / 2);  // most golden programs cut something
}

TEST(StreamedCc1, StreamedFileReadsBackAndWritesTheSameBytes) {
  for (const auto& in : corpus_inputs()) {
    SCOPED_TRACE(in.name);
    const std::string text = streamed(in).text;
    const auto back = step_writer::read_stepnc(text, "streamed.stp");
    EXPECT_TRUE(back.warnings.empty());
    EXPECT_TRUE(step_writer::write_stepnc(back.project, write_options()) == text);
  }
}

TEST(StreamedCc1, AnErrorMidProgramStopsTheStreamWithItsLocation) {
  const fs::path paper = kShared / "corpus/paper";
  Input in{"no tool", paper / "face_mill.ngc", {}, std::nullopt, {}};
  in.tools = setup::parse_tool_list(R"([{"number": 7, "type": "drill", "diameter": 5}])", "tools.json");
  const Written w = streamed(in);
  EXPECT_NE(w.error.find("face_mill.ngc:"), std::string::npos) << w.error;
  EXPECT_EQ(w.error, whole(in).error);
}

}  // namespace
}  // namespace ncbridge::cc1_builder::testing
