#include "ncbridge/bus/routed_writer.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "ncbridge/bus/bus_error.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/rendezvous.hpp"
#include "ncbridge/bus/routing.hpp"
#include "ncbridge/bus/wait_set.hpp"
#include "ncbridge/bus/worker_tracker.hpp"

namespace ncbridge::bus {

using Clock = std::chrono::steady_clock;

namespace {

std::string_view stage_of(Topic topic) {
  const auto stage = routed_to(topic);
  if (!stage) throw BusError(std::string(topic_name(topic)) + " is not routed to one worker");
  return *stage;
}

}  // namespace

struct RoutedWriter::State {
  State(Participant& p, Topic t, std::chrono::milliseconds settle)
      : participant(p),
        topic(t),
        stage(stage_of(t)),
        settle_until(Clock::now() + settle),
        workers(p, Topic::Workers),
        news(p) {
    news.attach(workers);
    follower = std::thread([this] { follow(); });
  }

  ~State() {
    stop = true;
    news.wake();
    follower.join();
  }

  struct Job {
    std::string worker;  // empty while it waits for one
    std::vector<Envelope> samples;
  };
  using JobKey = std::pair<std::string, std::string>;

  // The workers topic, until the writer goes: asleep until it says something (or the settle
  // time ends).
  void follow() {
    while (!stop) {
      std::vector<Received> got;
      try {
        const auto now = Clock::now();
        const auto sleep = settled || now >= settle_until
                               ? std::chrono::milliseconds(60'000)
                               : std::chrono::duration_cast<std::chrono::milliseconds>(settle_until - now) +
                                     std::chrono::milliseconds(1);
        news.wait(sleep);
        got = workers.take(std::chrono::milliseconds(0));
      } catch (const std::exception& e) {
        tell(std::string(topic_name(topic)) + ": cannot read the workers topic: " + e.what());
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        continue;
      }
      const std::lock_guard lock(mutex);
      bool changed = false;
      for (const Received& r : got) changed = tracker.apply(r) || changed;
      if (!settled && Clock::now() >= settle_until) settled = changed = true;
      if (!changed) continue;
      try {
        reassign();
      } catch (const std::exception& e) {
        tell(std::string(topic_name(topic)) + ": cannot send jobs to their new worker: " + e.what());
      }
      membership.notify_all();
    }
  }

  // Jobs whose worker left go to their owner among the live workers; waiting jobs to theirs.
  void reassign() {
    const std::vector<std::string> live = tracker.live_workers(stage);
    const auto is_live = [&](const std::string& w) { return std::binary_search(live.begin(), live.end(), w); };
    for (auto& [key, job] : jobs) {
      if (job.worker.empty() || is_live(job.worker)) continue;
      tell("job " + key.first + ": " + stage + " worker " + job.worker + " is gone; its " +
           std::string(topic_name(topic)) + " input goes to another");
      job.worker.clear();
    }
    std::erase_if(writers, [&](const auto& w) { return !is_live(w.first); });  // frees the gone worker's history
    // A writer for each live worker at once: it matches its reader before the first job comes.
    for (const std::string& w : live) writer_of(w);
    for (auto& [key, job] : jobs) {
      if (job.worker.empty()) assign(key, job, live);
    }
  }

  // Gives a waiting job to its owner and sends it everything written of it.
  void assign(const JobKey& key, Job& job, const std::vector<std::string>& live) {
    if (!settled || live.empty()) return;
    const std::string& worker = live[*rendezvous_owner(key.first, live)];
    Writer& writer = writer_of(worker);
    job.worker = worker;
    for (const Envelope& e : job.samples) writer.write(e);
    if (ever_assigned.contains(key)) {
      resent += job.samples.size();
      tell("job " + key.first + ": " + std::to_string(job.samples.size()) + " sample(s) of " +
           std::string(topic_name(topic)) + " sent again, to " + stage + " worker " + worker);
    }
    ever_assigned.insert(key);
  }

  void tell(const std::string& message) const {
    if (report) report(message);
  }

  Writer& writer_of(const std::string& worker) {
    auto it = writers.find(worker);
    if (it == writers.end())
      it = writers.emplace(worker, std::make_unique<Writer>(participant, topic, worker_partition(stage, worker))).first;
    return *it->second;
  }

  Participant& participant;
  const Topic topic;
  const std::string stage;
  const Clock::time_point settle_until;
  Reader workers;  // read by the follower thread only
  WaitSet news;     // the workers reader, and wake() to stop
  mutable std::mutex mutex;
  mutable std::condition_variable membership;
  WorkerTracker tracker;
  bool settled = false;
  std::map<std::string, std::unique_ptr<Writer>, std::less<>> writers;  // by worker id
  std::map<JobKey, Job> jobs;
  std::set<JobKey> ever_assigned;  // jobs sent to a worker before (a second send is a re-send)
  std::uint64_t resent = 0;
  std::function<void(const std::string&)> report;
  std::atomic<bool> stop{false};
  std::thread follower;  // last: started once everything else is there
};

RoutedWriter::RoutedWriter(Participant& participant, Topic topic, std::chrono::milliseconds settle)
    : state_(std::make_unique<State>(participant, topic, settle)) {}

RoutedWriter::~RoutedWriter() = default;

Topic RoutedWriter::topic() const { return state_->topic; }

void RoutedWriter::write(std::string_view key, std::string_view subkey, std::uint64_t seq, std::uint32_t kind,
                         bool last, std::string_view payload) {
  State& s = *state_;
  const std::lock_guard lock(s.mutex);
  const State::JobKey k{std::string(key), std::string(subkey)};
  State::Job& job = s.jobs[k];
  job.samples.push_back(Envelope{k.first, k.second, seq, kind, last, std::string(payload)});
  if (job.worker.empty()) {
    s.assign(k, job, s.tracker.live_workers(s.stage));
  } else {
    s.writer_of(job.worker).write(job.samples.back());
  }
}

void RoutedWriter::unregister(std::string_view key, std::string_view subkey) {
  State& s = *state_;
  const std::lock_guard lock(s.mutex);
  const State::JobKey k{std::string(key), std::string(subkey)};
  const auto it = s.jobs.find(k);
  if (it == s.jobs.end()) return;
  const std::string worker = it->second.worker;
  s.jobs.erase(it);
  s.ever_assigned.erase(k);
  if (const auto w = s.writers.find(worker); w != s.writers.end()) w->second->unregister(key, subkey);
}

bool RoutedWriter::wait_for_acks(std::chrono::milliseconds timeout) {
  State& s = *state_;
  const auto deadline = Clock::now() + timeout;
  std::unique_lock lock(s.mutex);
  const bool all_assigned = s.membership.wait_until(lock, deadline, [&] {
    return std::all_of(s.jobs.begin(), s.jobs.end(), [](const auto& j) { return !j.second.worker.empty(); });
  });
  if (!all_assigned) return false;
  for (auto& [worker, writer] : s.writers) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (!writer->wait_for_acks(std::max(left, std::chrono::milliseconds(0)))) return false;
  }
  return true;
}

bool RoutedWriter::wait_for_readers(std::uint32_t count, std::chrono::milliseconds timeout) const {
  const State& s = *state_;
  std::unique_lock lock(s.mutex);
  return s.membership.wait_for(lock, timeout,
                               [&] { return s.settled && s.tracker.live_workers(s.stage).size() >= count; });
}

std::optional<std::string> RoutedWriter::worker_of(std::string_view key, std::string_view subkey) const {
  const State& s = *state_;
  const std::lock_guard lock(s.mutex);
  const auto it = s.jobs.find({std::string(key), std::string(subkey)});
  if (it == s.jobs.end() || it->second.worker.empty()) return std::nullopt;
  return it->second.worker;
}

void RoutedWriter::report_to(std::function<void(const std::string&)> report) {
  const std::lock_guard lock(state_->mutex);
  state_->report = std::move(report);
}

std::uint64_t RoutedWriter::resent() const {
  const std::lock_guard lock(state_->mutex);
  return state_->resent;
}

}  // namespace ncbridge::bus
