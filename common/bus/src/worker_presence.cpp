#include "ncbridge/bus/worker_presence.hpp"

#include <unistd.h>

#include <array>
#include <chrono>

namespace ncbridge::bus {

WorkerPresence::WorkerPresence(Participant& participant, wire::WorkerInfo info)
    : writer_(participant, Topic::Workers), info_(std::move(info)) {
  announce();
}

WorkerPresence::~WorkerPresence() {
  try {
    writer_.dispose(info_.stage, info_.worker_id);
  } catch (...) {
    // Leaving anyway: readers learn it from the writer's deletion (autodispose) or the lease.
  }
}

void WorkerPresence::update_jobs(std::vector<std::string> jobs_in_progress) {
  info_.jobs_in_progress = std::move(jobs_in_progress);
  announce();
}

void WorkerPresence::announce() {
  writer_.write(info_.stage, info_.worker_id, seq_++, 0, false, wire::encode_worker(info_));
}

wire::WorkerInfo this_process_worker(std::string stage) {
  std::array<char, 256> host{};
  if (gethostname(host.data(), host.size() - 1) != 0) host[0] = '\0';
  wire::WorkerInfo w;
  w.stage = std::move(stage);
  w.host = host.data();
  w.pid = static_cast<std::uint32_t>(getpid());
  w.worker_id = w.host + "/" + std::to_string(w.pid);
  w.started_unix_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                          std::chrono::system_clock::now().time_since_epoch())
                          .count();
  return w;
}

}  // namespace ncbridge::bus
