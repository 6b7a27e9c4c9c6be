#include "ncbridge/wire/worker.hpp"

#include "parse_or_throw.hpp"
#include "worker.pb.h"

namespace ncbridge::wire {

std::string encode_worker(const WorkerInfo& worker) {
  pb::Worker m;
  m.set_stage(worker.stage);
  m.set_worker_id(worker.worker_id);
  m.set_host(worker.host);
  m.set_pid(worker.pid);
  m.set_started_unix_ms(worker.started_unix_ms);
  for (const std::string& j : worker.jobs_in_progress) m.add_jobs_in_progress(j);
  return m.SerializeAsString();
}

WorkerInfo decode_worker(std::string_view bytes) {
  pb::Worker m;
  detail::parse_or_throw(m, bytes, "worker");
  WorkerInfo w{m.stage(), m.worker_id(), m.host(), m.pid(), m.started_unix_ms(), {}};
  for (const auto& j : m.jobs_in_progress()) w.jobs_in_progress.push_back(j);
  return w;
}

}  // namespace ncbridge::wire
