// THE place where ncbridge's DDS QoS are decided.
//
// Job inputs (programs, blocks, canonical, workingsteps, features) are RELIABLE and
// TRANSIENT_LOCAL with a deep per-job history: a worker that joins late, or takes over from a
// dead one, gets the whole job again from the writer's history. The writer keeps a job's
// samples until it unregisters the job's instance (Writer::unregister), so its history holds
// only jobs in flight. KEEP_LAST, not KEEP_ALL, on the writer: Cyclone 0.10 never drops a
// KEEP_ALL transient-local history, unregistered or not (measured: tests/bus). Readers are
// KEEP_ALL, so a slow reader slows the writer (flow control) and never loses a sample.
// Results (part21: a file in pieces) keep every piece until the writer unregisters the file (its
// retention policy). State (status, workers) keeps the latest sample per instance, durable, so
// a late reader sees the current state. Workers carry a liveliness lease and dispose their
// instance when their writer is deleted: readers learn of a clean exit at once and of a crash
// when the lease (and the participant lease, deploy/cyclonedds/) runs out.
#include "ncbridge/bus/qos_profiles.hpp"

#include "dds_check.hpp"

namespace ncbridge::bus {
namespace {

// A job's stream may hold up to `depth` samples: canonical batches of 1024 calls give 4M calls.
QosProfile job_input(std::int32_t depth) {
  QosProfile p;
  p.reliable = true;
  p.durability = Durability::TransientLocal;
  p.history = History::KeepLast;
  p.depth = depth;
  p.reader_history = History::KeepAll;  // a reader never drops what it has not taken
  p.max_instances = 10'000;             // jobs in flight per writer
  p.max_blocking = std::chrono::milliseconds(10'000);
  return p;
}

QosProfile latest_state(std::int32_t reader_depth) {
  QosProfile p;
  p.reliable = true;
  p.durability = Durability::TransientLocal;
  p.history = History::KeepLast;
  p.depth = 1;
  p.reader_history = History::KeepLast;
  p.reader_depth = reader_depth;
  return p;
}

}  // namespace

QosProfile qos_profile(Topic topic) {
  switch (topic) {
    case Topic::Programs:
      return job_input(4);       // one sample a job; a resubmission replaces it
    case Topic::Blocks:
      return job_input(65'536);  // one sample an executed block, one instance a run
    case Topic::Canonical:
    case Topic::Workingsteps:
    case Topic::Features:
      return job_input(4096);
    case Topic::Part21:
      return job_input(4096);    // a file in pieces of ~1 MB, one instance a file
    case Topic::Status:
      return latest_state(64);  // a reader may fall behind a fast stage's progress reports
    case Topic::Workers: {
      QosProfile p = latest_state(1);
      p.liveliness_lease = std::chrono::milliseconds(1000);
      p.autodispose_unregistered = true;
      return p;
    }
  }
  return job_input(4096);
}

namespace detail {

QosPtr make_qos(const QosProfile& p, Endpoint endpoint) {
  QosPtr q(dds_create_qos());
  const auto blocking = DDS_MSECS(p.max_blocking.count());
  dds_qset_reliability(q.get(), p.reliable ? DDS_RELIABILITY_RELIABLE : DDS_RELIABILITY_BEST_EFFORT, blocking);
  dds_qset_durability(q.get(), p.durability == Durability::TransientLocal ? DDS_DURABILITY_TRANSIENT_LOCAL
                                                                          : DDS_DURABILITY_VOLATILE);
  const bool reader = endpoint == Endpoint::Reader;
  const auto unlimited_or = [](std::int32_t n) { return n < 0 ? DDS_LENGTH_UNLIMITED : n; };
  const History kind = reader ? p.reader_history : p.history;
  const std::int32_t depth = reader ? p.reader_depth : p.depth;
  const dds_history_kind_t history = kind == History::KeepAll ? DDS_HISTORY_KEEP_ALL : DDS_HISTORY_KEEP_LAST;
  dds_qset_history(q.get(), history, depth);
  if (p.durability == Durability::TransientLocal && !reader) {
    // What the writer keeps for late readers: its history (Cyclone's default keeps 1 sample).
    dds_qset_durability_service(q.get(), 0, history, depth, DDS_LENGTH_UNLIMITED, unlimited_or(p.max_instances),
                                kind == History::KeepAll ? DDS_LENGTH_UNLIMITED : depth);
  }
  dds_qset_resource_limits(q.get(), DDS_LENGTH_UNLIMITED, unlimited_or(p.max_instances), DDS_LENGTH_UNLIMITED);
  if (p.liveliness_lease.count() > 0)
    dds_qset_liveliness(q.get(), DDS_LIVELINESS_AUTOMATIC, DDS_MSECS(p.liveliness_lease.count()));
  if (!reader) dds_qset_writer_data_lifecycle(q.get(), p.autodispose_unregistered);
  return q;
}

}  // namespace detail
}  // namespace ncbridge::bus
