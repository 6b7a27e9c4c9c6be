#include "ncbridge/capture/run_tracker.hpp"

#include <exception>

namespace ncbridge::capture {
namespace {

// A run is taken to start at a later line (LinuxCNC's "run from line", a restart after a
// tool break) when the first line seen lies beyond this many moving blocks: one or two short
// moves (a rapid to where the tool already is) can pass between two samples, more cannot.
constexpr std::size_t kMovesBeforeRestart = 2;

}  // namespace

std::vector<RunEvent> RunTracker::observe(const ControllerSample& sample) {
  std::vector<RunEvent> out;
  if (wait_for_idle_) {
    if (sample.interp != ControllerSample::Interp::Idle) return out;
    wait_for_idle_ = false;
  }
  if (!running_) {
    const bool starts = sample.mode == ControllerSample::Mode::Auto && sample.interp != ControllerSample::Interp::Idle &&
                        !sample.fault && !sample.program.empty();
    if (!starts) return out;
    start(sample, out);
    if (!running_) {  // the program could not be loaded: this execution is not captured
      wait_for_idle_ = sample.interp != ControllerSample::Interp::Idle;
      return out;
    }
  } else if (sample.fault) {
    finish(true, sample.fault_reason.empty() ? "the controller stopped with a fault" : sample.fault_reason, out);
    wait_for_idle_ = sample.interp != ControllerSample::Interp::Idle;
    return out;
  } else if (sample.mode != ControllerSample::Mode::Auto) {
    finish(true, "the controller left automatic mode", out);
    wait_for_idle_ = sample.interp != ControllerSample::Interp::Idle;
    return out;
  }

  if (program_.order.empty()) {  // no program text: the blocks as the controller names them
    if (sample.block && sample.block != last_block_ && !sample.block->empty()) {
      publish({sample.line, *sample.block, true}, out);
    }
    last_block_ = sample.block;
  } else if (sample.line > 0) {
    advance_to(sample.line, out);
  }

  if (sample.interp == ControllerSample::Interp::Idle) {
    if (sample.completed || (!program_.order.empty() && reached_last_move()) ||
        (program_.order.empty() && !sample.fault)) {
      while (cursor_ < program_.order.size()) publish(program_.order[cursor_++], out);
      finish(false, "", out);
    } else {
      const std::string where = seen_line_ ? " at line " + std::to_string(program_.order[cursor_ - 1].line) : "";
      finish(true, "the program was stopped" + where + " before its end", out);
    }
  }
  return out;
}

std::vector<RunEvent> RunTracker::lost(const std::string& reason) {
  std::vector<RunEvent> out;
  if (running_) finish(true, reason, out);
  return out;
}

std::vector<RunEvent> RunTracker::gap(const std::string& reason) {
  std::vector<RunEvent> out;
  if (running_ && program_.order.empty()) finish(true, "blocks were lost: " + reason, out);
  return out;
}

void RunTracker::start(const ControllerSample& sample, std::vector<RunEvent>& out) {
  running_ = true;
  seen_line_ = false;
  cursor_ = 0;
  last_move_ = 0;
  published_ = 0;
  last_block_.reset();
  program_ = {};
  RunEvent start;
  start.kind = RunEvent::Kind::Start;
  start.text = sample.program;
  std::string failure;
  try {
    program_ = loader_(sample.program);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  for (std::size_t i = 0; i < program_.order.size(); ++i) {
    if (program_.order[i].moves) last_move_ = i + 1;
  }
  start.program_text = program_.text;
  start.tool_table = program_.tool_table;
  start.tool_table_inch = program_.tool_table_inch;
  if (failure.empty() && sample.line > 0 && !program_.order.empty()) {
    // Where the run starts: the first occurrence of the line seen; a start beyond the first
    // few moving blocks is a start from a line. The blocks before it that make no motion set
    // the modal state the controller ran with (units, plane, tool, spindle); they are published.
    std::size_t at = 0, moves_before = 0;
    while (at < program_.order.size() && program_.order[at].line != sample.line) {
      if (program_.order[at].moves) ++moves_before;
      ++at;
    }
    if (at < program_.order.size() && moves_before > kMovesBeforeRestart) {
      start.start_line = sample.line;
      out.push_back(start);
      for (std::size_t i = 0; i < at; ++i) {
        if (!program_.order[i].moves) publish(program_.order[i], out);
      }
      cursor_ = at;
      return;
    }
  }
  out.push_back(start);
  if (!failure.empty()) finish(true, "cannot read the program: " + failure, out);
}

void RunTracker::advance_to(std::uint32_t line, std::vector<RunEvent>& out) {
  // The line's next occurrence at or after the cursor (the current block may be seen again).
  std::size_t at = cursor_ > 0 && program_.order[cursor_ - 1].line == line ? cursor_ - 1 : cursor_;
  while (at < program_.order.size() && program_.order[at].line != line) ++at;
  if (at == program_.order.size()) return;  // not a line of this program's order (another file)
  seen_line_ = true;
  while (cursor_ <= at) publish(program_.order[cursor_++], out);
}

void RunTracker::publish(const ExecutedLine& block, std::vector<RunEvent>& out) {
  RunEvent e;
  e.kind = RunEvent::Kind::Block;
  e.text = block.text;
  e.line = block.line;
  out.push_back(std::move(e));
  ++published_;
}

void RunTracker::finish(bool aborted, std::string reason, std::vector<RunEvent>& out) {
  RunEvent end;
  end.kind = RunEvent::Kind::End;
  end.aborted = aborted;
  end.reason = std::move(reason);
  end.blocks = published_;
  out.push_back(std::move(end));
  running_ = false;
}

bool RunTracker::reached_last_move() const { return cursor_ >= last_move_; }

}  // namespace ncbridge::capture
