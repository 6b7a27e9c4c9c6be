#include "ncbridge/capture/mtconnect_run.hpp"

namespace ncbridge::capture {

std::vector<ControllerSample> MtconnectDevice::observe(const std::vector<MtconnectObservation>& observations) {
  std::vector<ControllerSample> out;
  for (const MtconnectObservation& o : observations) {
    if (o.device != device_) continue;
    const bool unavailable = o.value == "UNAVAILABLE";
    ControllerSample next = state_;
    next.completed = false;
    if (o.name == "Execution") {
      const std::string& v = o.value;
      if (v == "ACTIVE" || v == "WAIT") {
        next.interp = ControllerSample::Interp::Running;
      } else if (v == "FEED_HOLD" || v == "INTERRUPTED" || v == "OPTIONAL_STOP" || v == "PROGRAM_STOPPED" ||
                 v == "PROGRAM_OPTIONAL_STOP") {
        next.interp = ControllerSample::Interp::Paused;
      } else {  // READY, STOPPED, PROGRAM_COMPLETED, UNAVAILABLE
        next.interp = ControllerSample::Interp::Idle;
        next.completed = v == "PROGRAM_COMPLETED";
      }
    } else if (o.name == "ControllerMode") {
      next.mode = o.value == "AUTOMATIC" || unavailable          ? ControllerSample::Mode::Auto
                  : o.value == "MANUAL_DATA_INPUT"               ? ControllerSample::Mode::Mdi
                                                                 : ControllerSample::Mode::Manual;
    } else if (o.name == "Program") {
      next.program = unavailable ? "" : o.value;
    } else if (o.name == "LineNumber" || o.name == "Line") {
      if (!o.sub_type.empty() && o.sub_type != "ABSOLUTE") continue;
      long long line = 0;
      try {
        line = unavailable ? 0 : std::stoll(o.value);
      } catch (const std::exception&) {
        line = 0;
      }
      next.line = line > 0 ? static_cast<std::uint32_t>(line) : 0;
    } else if (o.name == "Block") {
      next.block = unavailable ? std::nullopt : std::optional<std::string>(o.value);
    } else {
      continue;
    }
    state_ = next;
    out.push_back(next);
  }
  return out;
}

SampleCursor::Accepted SampleCursor::accept(const MtconnectStreams& answer) {
  Accepted a;
  if (next_ && answer.instance_id != instance_) {
    a.lost = true;
    a.why = "the agent restarted (instance " + std::to_string(instance_) + " -> " + std::to_string(answer.instance_id) + ")";
    next_.reset();
  }
  if (next_ && answer.first_sequence > *next_) {
    a.lost = true;
    a.why = "the agent's buffer moved past sequence " + std::to_string(*next_) + " (its oldest is now " +
            std::to_string(answer.first_sequence) + ")";
  }
  instance_ = answer.instance_id;
  const std::uint64_t from = next_.value_or(0);
  for (const MtconnectObservation& o : answer.observations) {
    if (o.sequence >= from) a.fresh.push_back(o);
  }
  // The answer's nextSequence; an answer older than what we had (a retried request) never
  // moves us back.
  if (!next_ || answer.next_sequence > *next_) next_ = answer.next_sequence;
  return a;
}

}  // namespace ncbridge::capture
