#pragma once
// A worker's side of the workers topic: announces itself while it lives, disposes its
// instance when destroyed. A crash is seen by others through DDS liveliness.
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/writer.hpp"
#include "ncbridge/wire/worker.hpp"

namespace ncbridge::bus {

class WorkerPresence {
 public:
  WorkerPresence(Participant& participant, wire::WorkerInfo info);  // announces at once
  ~WorkerPresence();
  WorkerPresence(WorkerPresence&&) noexcept = default;
  WorkerPresence& operator=(WorkerPresence&&) noexcept = default;

  // Re-announces with the jobs now in progress.
  void update_jobs(std::vector<std::string> jobs_in_progress);
  const wire::WorkerInfo& info() const { return info_; }

 private:
  void announce();
  Writer writer_;
  wire::WorkerInfo info_;
  std::uint64_t seq_ = 0;
};

// The local host's name and this process's id, for WorkerInfo and default worker ids.
wire::WorkerInfo this_process_worker(std::string stage);

}  // namespace ncbridge::bus
