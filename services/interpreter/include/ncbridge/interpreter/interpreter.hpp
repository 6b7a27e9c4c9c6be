#pragma once
// The interpreter stage: a part program in some controller dialect -> NIST canonical calls.
// Programs are read as a stream (memory stays flat in program length). The first error stops
// interpretation and throws ncbridge::InputError naming file, line and column; calls already
// delivered to the sink stay delivered (callers that write files write atomically).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::interpreter {

enum class Dialect { Rs274Ngc, Fanuc, Mach3, Siemens840D, Heidenhain, Auto };

struct Options {
  Dialect dialect = Dialect::Rs274Ngc;
  setup::ToolList tools;                                  // lengths/diameters in mm
  std::vector<std::filesystem::path> subroutine_path;    // where `o<name> call` files are found
  // LinuxCNC reports a program that ends without M2/M30 or a closing `%` as an error, after
  // running it. Off: the end of the file ends the program quietly.
  bool require_program_end = true;
  // Loop iterations (while, do, repeat) and subroutine calls of the whole program, and a
  // canned cycle's L repeats times its pecks, may number at most this; past it interpretation
  // stops with an error at the loop or call, instead of running for ever (LinuxCNC has no
  // such bound).
  std::uint64_t max_loop_iterations = 1'000'000;
  // Heidenhain conversational F words: mm/min (the control's unit) unless the user says the
  // program was posted in mm/s (FreeCAD's Heidenhain post). Never guessed from the values.
  enum class FeedUnits { PerMinute, PerSecond };
  FeedUnits heidenhain_feed_units = FeedUnits::PerMinute;
  // What the interpreter reads although the controller's data is missing or the construct has
  // no motion of its own (G43 without a tool list, a machine builder's M code) is reported
  // here, with the place in the program. Unset: not reported.
  std::function<void(const SourceLocation& where, const std::string& message)> warning;
  // Refuse (a located InputError) what would otherwise be read with a warning.
  bool strict = false;
  // M codes that are the machine builder's machine functions (no motion), beyond the dialect
  // table's list (`machine_functions:`): read with a warning.
  std::vector<int> machine_functions;
};

// Interprets the program in `program`, streaming calls into `sink` (source_file, call..., end).
void interpret_file(const std::filesystem::path& program, const Options& options, canonical::Sink& sink);

// Same, for a program held in memory; `name` is used in source locations and errors.
void interpret_text(std::string_view text, const std::string& name, const Options& options,
                    canonical::Sink& sink);

}  // namespace ncbridge::interpreter
