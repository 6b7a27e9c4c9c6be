#include "ncbridge/interpreter/interpreter.hpp"

#include "control_flow.hpp"
#include "lowering/run_dialect.hpp"
#include "ncbridge/common/error.hpp"
#include "text_source.hpp"

namespace ncbridge::interpreter {

void interpret_file(const std::filesystem::path& program, const Options& options, canonical::Sink& sink) {
  if (lowering::interpret_dialect_file(program, options, sink)) return;  // Fanuc, Mach3, 840D, Heidenhain
  auto source = open_text_file(program);
  if (!source) throw InputError({program.string(), 0, 0}, "cannot open program file");
  ControlFlowRunner runner(options, sink);
  runner.run(std::move(source), program.string());
  sink.end();
}

void interpret_text(std::string_view text, const std::string& name, const Options& options,
                    canonical::Sink& sink) {
  if (lowering::interpret_dialect_text(text, name, options, sink)) return;  // Fanuc, Mach3, 840D, Heidenhain
  ControlFlowRunner runner(options, sink);
  runner.run(std::make_unique<MemoryTextSource>(text), name);
  sink.end();
}

}  // namespace ncbridge::interpreter
