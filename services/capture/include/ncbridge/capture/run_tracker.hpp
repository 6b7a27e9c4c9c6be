#pragma once
// Turns what a controller reports, sample by sample, into the runs it executes: a run start,
// every block it executed in order, and a run end that says whether the program ran to its
// end or was stopped. The adapters (LinuxCNC's status, an MTConnect agent's stream) feed it
// samples; the `ncbridge capture` command publishes the events on the blocks topic.
//
// Controllers report the line motion is on, not every block: blocks that make no motion
// (M3, G21) and short moves between two samples go unseen. The tracker walks the program's
// execution order (execution_order.hpp) forward to each line it is told of and publishes every
// block it passes, so a completed run publishes exactly the blocks the program executes.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/capture/execution_order.hpp"

namespace ncbridge::capture {

// One look at the controller.
struct ControllerSample {
  enum class Mode : std::uint8_t { Auto, Mdi, Manual };
  enum class Interp : std::uint8_t { Idle, Running, Paused };
  Mode mode = Mode::Auto;
  Interp interp = Interp::Idle;
  std::string program;            // the program the controller runs (auto mode)
  std::uint32_t line = 0;         // the program line motion is executing, 0 = none
  std::optional<std::string> block;  // the executing block's text, when the controller says it
  bool completed = false;         // the controller says the program ended normally
  bool fault = false;             // e-stop, machine off, an error: a run in progress is aborted
  std::string fault_reason;
};

// What a run executes, loaded when it starts.
struct RunProgram {
  std::string text;                   // the program file's text ("" when unknown)
  std::vector<ExecutedLine> order;    // its execution order (empty when the text is unknown)
  std::string tool_table;             // the controller's tool table (LinuxCNC .tbl), "" = none
  bool tool_table_inch = false;
};

struct RunEvent {
  enum class Kind : std::uint8_t { Start, Block, End };
  Kind kind = Kind::Block;
  std::string text;               // Start: the program path; Block: the block
  std::uint32_t line = 0;         // Block: its program line
  // Start:
  std::string program_text, tool_table;
  bool tool_table_inch = false;
  std::uint32_t start_line = 0;   // the run started at this line, not at the program's start
  // End:
  bool aborted = false;
  std::string reason;             // why it was aborted
  std::uint64_t blocks = 0;       // blocks published in the run
  friend bool operator==(const RunEvent&, const RunEvent&) = default;
};

class RunTracker {
 public:
  // Loads the program a new run executes (its text, order and the controller's tool table).
  // An exception from it ends the run before it starts: the tracker reports the run aborted.
  using Loader = std::function<RunProgram(const std::string& program)>;
  explicit RunTracker(Loader loader) : loader_(std::move(loader)) {}

  std::vector<RunEvent> observe(const ControllerSample& sample);
  // The controller is gone (connection lost, restarted): a run in progress ends aborted.
  std::vector<RunEvent> lost(const std::string& reason);
  // Some of the controller's reports were missed. A run that follows the program's lines
  // loses nothing (its execution order fills in); one that follows the block texts the
  // controller reports ends aborted, so a run with holes never looks complete.
  std::vector<RunEvent> gap(const std::string& reason);

  bool running() const { return running_; }

 private:
  void start(const ControllerSample& sample, std::vector<RunEvent>& out);
  void advance_to(std::uint32_t line, std::vector<RunEvent>& out);
  void publish(const ExecutedLine& block, std::vector<RunEvent>& out);
  void finish(bool aborted, std::string reason, std::vector<RunEvent>& out);
  bool reached_last_move() const;

  Loader loader_;
  bool running_ = false;
  bool wait_for_idle_ = false;  // a run ended while the controller still ran: no new run until it stops
  bool seen_line_ = false;
  RunProgram program_;
  std::size_t cursor_ = 0;            // next block of program_.order to publish
  std::size_t last_move_ = 0;         // index after the last moving block of the order
  std::optional<std::string> last_block_;
  std::uint64_t published_ = 0;
};

}  // namespace ncbridge::capture
