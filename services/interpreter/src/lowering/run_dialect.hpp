#pragma once
// The dialect front-ends behind interpret_file/interpret_text: picks the front-end for
// options.dialect (after detection for Auto) and runs the program through it.
#include <string>

#include "lowering/program_text.hpp"
#include "ncbridge/canonical/call.hpp"
#include "ncbridge/interpreter/interpreter.hpp"

namespace ncbridge::interpreter::lowering {

// Runs `program` with a non-RS274 front-end. False (and nothing run) when `dialect` is
// RS274/NGC, which the caller runs itself.
bool run_dialect(Dialect dialect, ProgramText program, const Options& options, canonical::Sink& sink);

// The dialect to run: options.dialect, or the detected one for Auto (read, when no construct
// decides: detect_dialect_reading).
Dialect resolve_dialect(const Options& options, std::string_view text, const std::string& name);

}  // namespace ncbridge::interpreter::lowering

namespace ncbridge::interpreter::lowering {

// The hooks of interpret_file / interpret_text: when the program's dialect (options.dialect,
// or the detected one for Auto) is not RS274/NGC, run it here, end the sink and return true;
// return false for RS274/NGC, which the caller runs itself.
bool interpret_dialect_file(const std::filesystem::path& program, const Options& options, canonical::Sink& sink);
bool interpret_dialect_text(std::string_view text, const std::string& name, const Options& options,
                            canonical::Sink& sink);

}  // namespace ncbridge::interpreter::lowering
