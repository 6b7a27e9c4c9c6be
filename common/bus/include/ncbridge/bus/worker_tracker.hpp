#pragma once
// Which workers of each stage are alive, from what the workers topic says (no DDS in here:
// feed it Received samples, or call alive/gone directly), and who owns a job.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/bus/envelope.hpp"

namespace ncbridge::bus {

class WorkerTracker {
 public:
  // Each returns true when the set of live workers changed.
  bool alive(std::string_view stage, std::string_view worker_id);
  bool gone(std::string_view stage, std::string_view worker_id);
  // A sample or instance-state change of the workers topic (key = stage, subkey = worker_id):
  // data on a live instance announces the worker; Disposed or NoWriters removes it.
  bool apply(const Received& received);

  // Live workers of a stage, sorted by id.
  std::vector<std::string> live_workers(std::string_view stage) const;
  // The live worker of `stage` that owns `job_id` (rendezvous hashing); nullopt if none lives.
  std::optional<std::string> owner(std::string_view stage, std::string_view job_id) const;
  bool owns(std::string_view stage, std::string_view worker_id, std::string_view job_id) const;

  // Increases at every membership change: a stage re-checks the ownership of its pending jobs
  // when this moves.
  std::uint64_t generation() const { return generation_; }

 private:
  std::map<std::string, std::set<std::string>, std::less<>> live_;  // stage -> worker ids
  std::uint64_t generation_ = 0;
};

}  // namespace ncbridge::bus
