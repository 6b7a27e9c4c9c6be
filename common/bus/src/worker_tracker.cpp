#include "ncbridge/bus/worker_tracker.hpp"

#include "ncbridge/bus/rendezvous.hpp"

namespace ncbridge::bus {

bool WorkerTracker::alive(std::string_view stage, std::string_view worker_id) {
  auto it = live_.find(stage);
  if (it == live_.end()) it = live_.emplace(std::string(stage), std::set<std::string>{}).first;
  const bool added = it->second.emplace(worker_id).second;
  if (added) ++generation_;
  return added;
}

bool WorkerTracker::gone(std::string_view stage, std::string_view worker_id) {
  const auto it = live_.find(stage);
  if (it == live_.end()) return false;
  const auto w = it->second.find(std::string(worker_id));
  if (w == it->second.end()) return false;
  it->second.erase(w);
  ++generation_;
  return true;
}

bool WorkerTracker::apply(const Received& r) {
  if (r.state != InstanceState::Alive) return gone(r.envelope.key, r.envelope.subkey);
  if (r.has_data) return alive(r.envelope.key, r.envelope.subkey);
  return false;
}

std::vector<std::string> WorkerTracker::live_workers(std::string_view stage) const {
  const auto it = live_.find(stage);
  if (it == live_.end()) return {};
  return {it->second.begin(), it->second.end()};
}

std::optional<std::string> WorkerTracker::owner(std::string_view stage, std::string_view job_id) const {
  const std::vector<std::string> workers = live_workers(stage);
  const auto i = rendezvous_owner(job_id, workers);
  if (!i) return std::nullopt;
  return workers[*i];
}

bool WorkerTracker::owns(std::string_view stage, std::string_view worker_id, std::string_view job_id) const {
  const auto o = owner(stage, job_id);
  return o && *o == worker_id;
}

}  // namespace ncbridge::bus
