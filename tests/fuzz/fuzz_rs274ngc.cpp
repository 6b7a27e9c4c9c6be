// libFuzzer target: arbitrary bytes as an RS274/NGC program. The interpreter must either finish
// or throw ncbridge::InputError; anything else (a crash, a sanitizer report, another exception,
// a hang past libFuzzer's -timeout) is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace {

class DiscardingSink final : public ncbridge::canonical::Sink {
 public:
  void call(const ncbridge::canonical::Call&) override {}
};

// A few tools, so that tool changes, length offsets and cutter compensation are reachable.
ncbridge::interpreter::Options fuzz_options() {
  using ncbridge::setup::Tool;
  ncbridge::interpreter::Options options;
  std::vector<Tool> tools;
  for (int number = 1; number <= 4; ++number) {
    Tool tool;
    tool.number = number;
    tool.pocket = number;
    tool.diameter = 2.0 * number;
    tool.length = 40.0 + 10.0 * number;
    tools.push_back(tool);
  }
  options.tools = ncbridge::setup::ToolList(std::move(tools));
  options.max_loop_iterations = 20000;  // an endless loop ends in an error well within -timeout
  return options;  // no subroutine path: fuzzed programs never read files
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const ncbridge::interpreter::Options options = fuzz_options();
  const std::string_view program(reinterpret_cast<const char*>(data), size);
  DiscardingSink sink;
  try {
    ncbridge::interpreter::interpret_text(program, "fuzz.ngc", options, sink);
  } catch (const ncbridge::InputError&) {
    // Bad input reported as it should be.
  }
  return 0;
}
