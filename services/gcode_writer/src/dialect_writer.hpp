#pragma once
// What every dialect writer does for the ProgramWriter (program_writer.cpp): bring the reader
// to a machine state, write one action (a move, an arc, a dwell, a tool change, a stop, ...),
// write a canned cycle's hole as the dialect's cycle when it makes the same motion. Each keeps
// `reader()`: the state the dialect's front-end will be in after the text written so far,
// updated with the calls its words make that front-end emit.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "machine_state.hpp"
#include "ncbridge/canonical/call.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/gcode_writer/options.hpp"
#include "text_output.hpp"

namespace ncbridge::gcode_writer {

// What of the machine state an action depends on (the writer brings these to the asked-for
// state before it; the round-trip tests compare the same).
enum Need : unsigned {
  kActuators = 1u << 0,  // spindle direction and speed, spindle mode, coolant
  kFrame = 1u << 1,      // units, work offsets and XY rotation, G92 offset, tool length offset
  kFeed = 1u << 2,       // feed rate, feed mode and reference, overrides
  kPlane = 1u << 3,      // the plane (arcs, cycles)
  kPath = 1u << 4,       // path control mode and tolerances (feed motions)
  kToolSelect = 1u << 5, // the selected tool (T)
  kUnits = 1u << 6,      // only the units (actions with lengths)
};
constexpr unsigned kMotion = kActuators | kFrame | kToolSelect;
constexpr unsigned kFeedMotion = kMotion | kFeed | kPath;

// One hole of a canned cycle: the calls the cycle made for it, all with the same cycle id.
struct Hole {
  canonical::CycleTag tag;
  std::vector<canonical::Call> calls;
};

// Where the writer is in the source: errors name it.
struct WriterLocation {
  std::string file;
  std::uint32_t line = 0;
};

class DialectWriter {
 public:
  DialectWriter(const Options& options, TextOutput& out, const WriterLocation& where)
      : options_(options), out_(out), where_(where) {}
  virtual ~DialectWriter() = default;
  DialectWriter(const DialectWriter&) = delete;
  DialectWriter& operator=(const DialectWriter&) = delete;

  MachineState& reader() { return reader_; }
  const MachineState& reader() const { return reader_; }

  // The program's start, in the units and plane `desired` begins with.
  virtual void begin_program(const MachineState& desired) = 0;
  // Brings the reader to `desired` in what `need` names; refuses what the dialect cannot set.
  virtual void sync(const MachineState& desired, unsigned need) = 0;
  virtual void traverse(const canonical::Pose& end) = 0;
  virtual void feed(const canonical::Pose& end) = 0;
  virtual void arc(const canonical::ArcFeed& arc) = 0;
  // False: an arc of several turns is handed over one turn at a time (arc_turns.hpp).
  virtual bool arcs_turn_more_than_once() const { return true; }
  virtual void dwell(double seconds) = 0;
  // M6 of the selected tool (the reader emits START_CHANGE, STOP_SPINDLE_TURNING, CHANGE_TOOL).
  virtual void tool_change(int tool) = 0;
  // Any other action call: stops, spindle orientation, tool table entries, probes, ...
  virtual void action(const canonical::Call& call, const MachineState& desired) = 0;
  // The hole as the dialect's cycle, when that makes the same motion from here (`desired`
  // is the state the hole starts in); false: the caller writes its calls as moves.
  virtual bool cycle(const Hole& hole, const MachineState& desired) = 0;
  // Ends a run of cycle blocks (G80) before anything else is written.
  virtual void end_cycles() {}
  virtual void comment(std::string_view text) = 0;
  virtual void message(std::string_view text) = 0;
  // M2 (rewind false) or M30 (true).
  virtual void program_end(bool rewind) = 0;
  // The end of the text: after program_end(), or (ended false) a program that stopped at its
  // end of tape (a %-delimited program without M2/M30).
  virtual void end_program(bool ended) = 0;
  virtual void begin_repeat(std::uint32_t count, double z_shift) = 0;
  virtual void end_repeat() = 0;

 protected:
  [[noreturn]] void refuse(const std::string& construct, const std::string& why = {}) const;
  int length_decimals() const;  // digits for lengths in the reader's current units

  const Options& options_;
  TextOutput& out_;
  const WriterLocation& where_;
  MachineState reader_;
};

std::unique_ptr<DialectWriter> make_rs274ngc_writer(const Options&, TextOutput&, const WriterLocation&);
std::unique_ptr<DialectWriter> make_fanuc_writer(const Options&, TextOutput&, const WriterLocation&);
std::unique_ptr<DialectWriter> make_mach3_writer(const Options&, TextOutput&, const WriterLocation&);
std::unique_ptr<DialectWriter> make_siemens840d_writer(const Options&, TextOutput&, const WriterLocation&);
std::unique_ptr<DialectWriter> make_heidenhain_writer(const Options&, TextOutput&, const WriterLocation&);

}  // namespace ncbridge::gcode_writer
