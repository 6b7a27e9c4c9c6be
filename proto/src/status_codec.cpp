#include "ncbridge/wire/status.hpp"

#include "parse_or_throw.hpp"
#include "status.pb.h"

namespace ncbridge::wire {

std::string encode_status(const JobStatus& status) {
  pb::JobStatus m;
  m.set_job_id(status.job_id);
  m.set_stage(status.stage);
  m.set_worker_id(status.worker_id);
  m.set_state(static_cast<pb::JobState>(status.state));
  m.set_progress(status.progress);
  m.set_message(status.message);
  if (!status.where.file.empty() || status.where.line != 0 || status.where.column != 0) {
    auto* w = m.mutable_where();
    w->set_file(status.where.file);
    w->set_line(status.where.line);
    w->set_column(status.where.column);
  }
  return m.SerializeAsString();
}

JobStatus decode_status(std::string_view bytes) {
  using namespace detail;
  pb::JobStatus m;
  parse_or_throw(m, bytes, "job status");
  JobStatus s;
  s.job_id = m.job_id();
  s.stage = m.stage();
  s.worker_id = m.worker_id();
  s.state = enum_in_range<JobState>(m.state(), 7, "job status", "state");
  s.progress = m.progress();
  s.message = m.message();
  s.where = {m.where().file(), m.where().line(), m.where().column()};
  return s;
}

JobStatus error_status(std::string job_id, std::string stage, std::string worker_id, const InputError& error) {
  JobStatus s;
  s.job_id = std::move(job_id);
  s.stage = std::move(stage);
  s.worker_id = std::move(worker_id);
  s.state = JobState::Error;
  s.message = error.message();
  s.where = error.where();
  return s;
}

}  // namespace ncbridge::wire
