#pragma once
// The live workers of every stage, kept up to date from the workers topic.
#include <chrono>
#include <optional>
#include <string>
#include <string_view>

#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/worker_tracker.hpp"

namespace ncbridge::bus {

class WorkerDirectory {
 public:
  explicit WorkerDirectory(Participant& participant);

  // Applies what the workers topic said, waiting up to `timeout` for news; true when the
  // membership changed.
  bool poll(std::chrono::milliseconds timeout);

  const WorkerTracker& tracker() const { return tracker_; }
  const Reader& reader() const { return reader_; }  // to wait on it with others (bus::WaitSet)
  std::optional<std::string> owner(std::string_view stage, std::string_view job_id) const {
    return tracker_.owner(stage, job_id);
  }

 private:
  Reader reader_;
  WorkerTracker tracker_;
};

}  // namespace ncbridge::bus
