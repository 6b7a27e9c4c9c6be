// libFuzzer target: arbitrary bytes as a part program in one dialect (NCBRIDGE_FUZZ_DIALECT, set
// per target in CMakeLists.txt): the dialect's reader, its control flow, the lowering and the
// RS274 executor. The interpreter must either finish or throw ncbridge::InputError with a
// location; anything else (a crash, a sanitizer report, another exception, a hang past
// libFuzzer's -timeout) is a bug. Seeds: tests/fuzz/corpus/<dialect>/ and tests/interpreter/dialects/<dialect>/.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace {

class DiscardingSink final : public ncbridge::canonical::Sink {
 public:
  void call(const ncbridge::canonical::Call&) override {}
};

// A few tools with names and sizes, so that tool changes, length offsets, cutter compensation,
// tools called by name and cycles that need a tool diameter are reachable.
ncbridge::interpreter::Options fuzz_options() {
  using ncbridge::setup::Tool;
  ncbridge::interpreter::Options options;
  options.dialect = ncbridge::interpreter::Dialect::NCBRIDGE_FUZZ_DIALECT;
  options.max_loop_iterations = 20'000;  // endless loops end in an error well within -timeout
  std::vector<Tool> tools;
  for (int number = 1; number <= 4; ++number) {
    Tool tool;
    tool.number = number;
    tool.pocket = number;
    tool.name = "T" + std::to_string(number);
    tool.diameter = 2.0 * number;
    tool.length = 40.0 + 10.0 * number;
    tools.push_back(tool);
  }
  options.tools = ncbridge::setup::ToolList(std::move(tools));
  return options;  // no subroutine path: fuzzed programs read no other files
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const ncbridge::interpreter::Options options = fuzz_options();
  const std::string_view program(reinterpret_cast<const char*>(data), size);
  DiscardingSink sink;
  try {
    ncbridge::interpreter::interpret_text(program, NCBRIDGE_FUZZ_FILE_NAME, options, sink);
  } catch (const ncbridge::InputError&) {
    // Bad input reported as it should be.
  }
  return 0;
}
