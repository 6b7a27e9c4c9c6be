// libFuzzer target: the STEP-NC -> canonical calls -> program path. A Part 21 file the CC1 reader
// accepts goes through the STEP-NC interpreter into the writer of a dialect (the input's first
// byte picks it, and whether toolpaths are in the feature or the setup frame); what cannot be
// read or written is an InputError, never a crash.
#include <cstdint>
#include <string>
#include <string_view>

#include "ncbridge/common/error.hpp"
#include "ncbridge/gcode_writer/program_writer.hpp"
#include "ncbridge/gcode_writer/stepnc_interpreter.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncbridge;
  if (size == 0) return 0;
  const std::uint8_t pick = data[0];
  std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    const auto read = step_writer::read_stepnc(text, "fuzz.stp");
    gcode_writer::Options options;
    options.dialect = static_cast<gcode_writer::Dialect>(pick % 5);
    options.tools = gcode_writer::stepnc_tools(read.project);
    options.comments = (pick & 0x20) != 0 ? gcode_writer::Comments::Source : gcode_writer::Comments::Program;
    gcode_writer::StepncOptions stepnc;
    stepnc.toolpath_frame = (pick & 0x10) != 0 ? gcode_writer::StepncOptions::ToolpathFrame::Setup
                                               : gcode_writer::StepncOptions::ToolpathFrame::Feature;
    stepnc.name_workingsteps = (pick & 0x20) != 0;
    std::uint64_t written = 0;
    gcode_writer::ProgramWriter writer(options, [&](std::string_view piece) { written += piece.size(); });
    gcode_writer::interpret_stepnc(read.project, "fuzz.stp", stepnc, writer);
  } catch (const InputError&) {
  }
  return 0;
}
