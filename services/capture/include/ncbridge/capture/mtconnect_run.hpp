#pragma once
// From an MTConnect agent's observations to controller samples for the run tracker, and the
// bookkeeping of polling an agent's /sample: which sequence to ask for next, what was already
// seen (answers may overlap or come out of order), and when observations were lost (the agent's
// buffer moved past what we had read, or the agent restarted).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/capture/mtconnect_streams.hpp"
#include "ncbridge/capture/run_tracker.hpp"

namespace ncbridge::capture {

// The state of one device's controller path, as its observations tell it.
//   Execution: ACTIVE, WAIT -> running; FEED_HOLD, INTERRUPTED, OPTIONAL_STOP, PROGRAM_STOPPED,
//   PROGRAM_OPTIONAL_STOP -> paused; READY, STOPPED -> idle; PROGRAM_COMPLETED -> idle, ended
//   normally. ControllerMode AUTOMATIC -> auto, MANUAL_DATA_INPUT -> MDI, others manual.
//   Program -> the program; LineNumber / Line (ABSOLUTE or no subType) -> the line; Block -> the
//   block's text. UNAVAILABLE leaves the item unknown.
class MtconnectDevice {
 public:
  explicit MtconnectDevice(std::string device) : device_(std::move(device)) {}
  // One sample per observation of this device that changes what a sample says.
  std::vector<ControllerSample> observe(const std::vector<MtconnectObservation>& observations);
  const std::string& device() const { return device_; }

 private:
  std::string device_;
  ControllerSample state_;
};

// Polling /sample?from=NEXT: accept() takes an answer and returns the observations not seen
// before, in order; `lost` tells that some were missed since the last answer.
class SampleCursor {
 public:
  struct Accepted {
    std::vector<MtconnectObservation> fresh;
    bool lost = false;            // observations were missed (buffer overrun, agent restart)
    std::string why;
  };
  // The first answer (/current, or /sample) sets where we are.
  Accepted accept(const MtconnectStreams& answer);
  std::optional<std::uint64_t> next() const { return next_; }
  // What we had is gone from the agent: the next answer (a /current) is taken whole.
  void resync() { next_.reset(); }

 private:
  std::optional<std::uint64_t> next_;
  std::uint64_t instance_ = 0;
};

}  // namespace ncbridge::capture
