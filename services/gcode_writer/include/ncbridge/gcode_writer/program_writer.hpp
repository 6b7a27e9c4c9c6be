#pragma once
// The gcode_writer stage: a canonical call stream written as a program in a controller's
// dialect, the inverse of the interpreter's front-ends: what it writes, the front-end of that
// dialect reads back into the same motion (docs/gcode.md).
//
// The writer keeps a model of the state the target's reader will be in after the text written
// so far, and the state the incoming calls ask for. State calls (feed, speed, units, offsets,
// coolant, ...) only change what is asked for; before each motion the writer writes what it
// takes to bring the reader to that state (so a redundant call writes nothing), then the move.
// The calls of a canned cycle (Call::cycle) are written back as the dialect's cycle when that
// cycle makes the same motion, else as the moves themselves. What the dialect cannot express
// is refused with an InputError naming the construct, the dialect and the source line.
//
// Text goes to the output as it is made (in pieces of about 64 KiB): memory stays flat in
// program length. Callers that write files write them atomically (step_writer::AtomicFile).
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/gcode_writer/options.hpp"

namespace ncbridge::gcode_writer {

class ProgramWriter final : public canonical::Sink {
 public:
  using Output = std::function<void(std::string_view)>;
  ProgramWriter(Options options, Output output);
  ~ProgramWriter() override;
  ProgramWriter(const ProgramWriter&) = delete;
  ProgramWriter& operator=(const ProgramWriter&) = delete;

  void source_file(std::uint32_t index, std::string_view path) override;
  void call(const canonical::Call& call) override;
  // Writes the program's end (and the subprograms of repeat constructs) and flushes.
  void end() override;

  // The repeat construct (for the toolpath optimizer): the calls between begin_repeat() and
  // end_repeat() are the first copy of a body that the program runs `count` times, each copy
  // shifted by `z_shift` along Z from the one before. The body must end where it began shifted
  // by z_shift (so that the copies join up) and may hold moves, arcs, feed rates and comments
  // only. It is written once, in incremental coordinates: `o<n> repeat [count]` (RS274/NGC), a
  // subprogram called with M98 P.. L.. (Fanuc, Mach3), REPEAT ... UNTIL (SINUMERIK), LBL n ...
  // CALL LBL n REP (Heidenhain). After end_repeat() the tool is where the last copy ended.
  void begin_repeat(std::uint32_t count, double z_shift);
  void end_repeat();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A whole call stream written to a string (tests, small programs).
std::string write_program(std::span<const canonical::Call> calls, const Options& options);

}  // namespace ncbridge::gcode_writer
