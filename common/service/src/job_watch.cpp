#include "ncbridge/service/job_watch.hpp"

#include "ncbridge/common/error.hpp"
#include "ncbridge/service/sha256.hpp"

namespace ncbridge::service {

JobWatch::JobWatch(bus::Participant& participant, std::string job_id)
    : job_id_(std::move(job_id)), status_(participant, bus::Topic::Status), part21_(participant, bus::Topic::Part21) {}

JobOutcome JobWatch::wait(std::chrono::milliseconds timeout,
                          const std::function<void(const wire::JobStatus&)>& on_status) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + timeout;
  JobOutcome outcome;
  while (Clock::now() < deadline) {
    for (const bus::Received& r : status_.take(std::chrono::milliseconds(0))) {
      if (!r.has_data || r.envelope.key != job_id_) continue;
      const wire::JobStatus s = wire::decode_status(r.envelope.payload);
      if (on_status) on_status(s);
      if (s.state == wire::JobState::Error) {
        outcome.error = s;
        return outcome;
      }
    }
    for (const bus::Received& r : part21_.take(std::chrono::milliseconds(20))) {
      if (!r.has_data || r.envelope.key != job_id_) continue;
      wire::Part21File file = wire::decode_part21(r.envelope.payload);
      if (sha256(file.content) != file.sha256)
        throw InputError({"<part21 file>", 0, 0}, "the file of job " + job_id_ + " does not match its SHA-256 digest");
      outcome.file = std::move(file);
      return outcome;
    }
  }
  return outcome;
}

}  // namespace ncbridge::service
