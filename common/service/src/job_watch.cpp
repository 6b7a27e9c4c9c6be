#include "ncbridge/service/job_watch.hpp"

#include "ncbridge/common/error.hpp"
#include "ncbridge/service/sha256.hpp"

namespace ncbridge::service {

JobWatch::JobWatch(bus::Participant& participant, std::string job_id)
    : JobWatch(participant, std::vector<std::string>{std::move(job_id)}) {}

JobWatch::JobWatch(bus::Participant& participant, std::vector<std::string> job_ids)
    : pending_(job_ids.begin(), job_ids.end()),
      status_(participant, bus::Topic::Status),
      part21_(participant, bus::Topic::Part21),
      wait_set_(participant) {
  wait_set_.attach(status_);
  wait_set_.attach(part21_);
}

JobOutcome JobWatch::wait(std::chrono::milliseconds timeout,
                          const std::function<void(const wire::JobStatus&)>& on_status) {
  JobOutcome outcome;
  wait_all(timeout, [&](const std::string&, JobOutcome o) { outcome = std::move(o); }, on_status);
  return outcome;
}

std::set<std::string> JobWatch::wait_all(std::chrono::milliseconds timeout,
                                         const std::function<void(const std::string&, JobOutcome)>& on_over,
                                         const std::function<void(const wire::JobStatus&)>& on_status) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + timeout;
  while (!pending_.empty()) {
    for (const bus::Received& r : status_.take(std::chrono::milliseconds(0), 4096)) {
      if (!r.has_data || !pending_.contains(r.envelope.key)) continue;
      const wire::JobStatus s = wire::decode_status(r.envelope.payload);
      if (on_status) on_status(s);
      if (s.state == wire::JobState::Error) {
        pending_.erase(r.envelope.key);
        JobOutcome o;
        o.error = s;
        on_over(r.envelope.key, std::move(o));
      }
    }
    for (const bus::Received& r : part21_.take(std::chrono::milliseconds(0))) {
      if (!r.has_data || !pending_.contains(r.envelope.key)) continue;
      wire::Part21File file = wire::decode_part21(r.envelope.payload);
      if (sha256(file.content) != file.sha256)
        throw InputError({"<part21 file>", 0, 0}, "the file of job " + r.envelope.key + " does not match its SHA-256 digest");
      pending_.erase(r.envelope.key);
      JobOutcome o;
      o.file = std::move(file);
      on_over(r.envelope.key, std::move(o));
    }
    const auto now = Clock::now();
    if (pending_.empty() || now >= deadline) break;
    wait_set_.wait(std::min(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now), std::chrono::milliseconds(200)));
  }
  return pending_;
}

}  // namespace ncbridge::service
