#include "ncbridge/interpreter/interpreter.hpp"

#include "control_flow.hpp"
#include "ncbridge/common/error.hpp"
#include "text_source.hpp"

namespace ncbridge::interpreter {

namespace {
void check_dialect(const Options& options, const std::string& name) {
  if (options.dialect != Dialect::Rs274Ngc && options.dialect != Dialect::Auto) {
    throw InputError({name, 0, 0}, "only the RS274/NGC (LinuxCNC) dialect is implemented so far");
  }
}
}  // namespace

void interpret_file(const std::filesystem::path& program, const Options& options, canonical::Sink& sink) {
  check_dialect(options, program.string());
  auto source = open_text_file(program);
  if (!source) throw InputError({program.string(), 0, 0}, "cannot open program file");
  ControlFlowRunner runner(options, sink);
  runner.run(std::move(source), program.string());
  sink.end();
}

void interpret_text(std::string_view text, const std::string& name, const Options& options,
                    canonical::Sink& sink) {
  check_dialect(options, name);
  ControlFlowRunner runner(options, sink);
  runner.run(std::make_unique<MemoryTextSource>(text), name);
  sink.end();
}

}  // namespace ncbridge::interpreter
