#include "program_pipeline.hpp"

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/feature_recognizer/cc1_input.hpp"
#include "ncbridge/feature_recognizer/recognizer.hpp"
#include "ncbridge/feature_recognizer/to_stepnc.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::test_support {

namespace fs = std::filesystem;

PipelineResult run_forward_pipeline(const fs::path& program, const fs::path& tools, const fs::path& stock) {
  std::ifstream in(program, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string stripped = std::regex_replace(text.str(), std::regex(R"(\([^)\n]*\))"), "");
  stripped = std::regex_replace(stripped, std::regex(";[^\n]*"), "");
  const fs::path copy = fs::temp_directory_path() / ("ncbridge_pipeline_" + program.parent_path().filename().string() + "_" +
                                                     program.filename().string());
  std::ofstream(copy, std::ios::binary) << stripped;

  PipelineResult out;
  cc1_builder::Options options;
  options.tools = setup::read_tool_list(tools);
  out.stock = setup::read_stock(stock);
  options.stock = out.stock;
  cc1_builder::Cc1Builder builder(options);
  interpreter::Options io;
  io.tools = options.tools;
  interpreter::interpret_file(copy, io, builder);
  fs::remove(copy);
  out.cc1 = builder.take_project();
  const auto features = feature_recognizer::recognize(feature_recognizer::workingsteps_from_cc1(out.cc1), out.stock);
  out.cc2 = feature_recognizer::cc2_from_cc1(out.cc1, features).project;
  return out;
}

namespace {

interpreter::Dialect dialect_of(const std::string& name) {
  if (name == "rs274ngc") return interpreter::Dialect::Rs274Ngc;
  if (name == "fanuc") return interpreter::Dialect::Fanuc;
  if (name == "mach3") return interpreter::Dialect::Mach3;
  if (name == "siemens840d") return interpreter::Dialect::Siemens840D;
  if (name == "heidenhain") return interpreter::Dialect::Heidenhain;
  throw std::invalid_argument("no dialect " + name);
}

}  // namespace

PipelineResult run_forward_pipeline(const ProgramInput& input) {
  PipelineResult out;
  cc1_builder::Options options;
  options.tools = setup::read_tool_list(input.tools);
  out.stock = setup::read_stock(input.stock);
  options.stock = out.stock;
  cc1_builder::Cc1Builder builder(options);
  interpreter::Options io;
  io.tools = options.tools;
  io.dialect = dialect_of(input.dialect);
  io.subroutine_path = input.subroutine_path;
  io.require_program_end = false;
  interpreter::interpret_file(input.program, io, builder);
  out.cc1 = builder.take_project();
  const auto features = feature_recognizer::recognize(feature_recognizer::workingsteps_from_cc1(out.cc1), out.stock);
  out.cc2 = feature_recognizer::cc2_from_cc1(out.cc1, features).project;
  return out;
}

CorpusPart corpus_part(const std::string& name) {
  const fs::path shared = NCBRIDGE_SHARED_DIR;
  const fs::path cam = shared / "corpus" / "cam", paper = shared / "corpus" / "paper";
  const fs::path parts = fs::path(NCBRIDGE_SOURCE_DIR) / "tests" / "cc2" / "parts";
  if (name == "face_mill" || name == "test_part") return {name, paper / (name + ".ngc"), paper / "tools.json", paper / "stock.json"};
  for (const auto& [part, program] : {std::pair{"p01_block_reference", "part.nc"}, {"p02_plate_center_zero", "part.linuxcnc.ngc"},
                                      {"p03_bracket_steps", "part.nc"}, {"p04_open_pockets", "part.linuxcnc.ngc"},
                                      {"p05_slots", "part.nc"}}) {
    if (name == part) return {name, cam / part / program, cam / part / "tools.json", cam / part / "stock.json"};
  }
  if (fs::exists(parts / name)) return {name, parts / name / "part.ngc", parts / name / "tools.json", parts / name / "stock.json"};
  throw std::invalid_argument("no corpus part " + name);
}

}  // namespace ncbridge::test_support
