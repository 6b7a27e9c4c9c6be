// libFuzzer target: CC2 input to the toolpath generator. A Part 21 file the STEP-NC reader
// accepts is given toolpaths (docs/toolpaths.md); what cannot be read or generated is an
// InputError naming the file, never a crash.
#include <cstdint>
#include <string_view>

#include "ncbridge/common/error.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/toolpath_generator/toolpath_generator.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncbridge;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto read = step_writer::read_stepnc(text, "fuzz.stp");
    toolpath_generator::Options options;
    options.source_name = "fuzz.stp";
    const auto generated = toolpath_generator::generate_toolpaths(read.project, options);
    (void)generated;
  } catch (const InputError&) {
  }
  return 0;
}
