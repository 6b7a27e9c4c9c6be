#include "ncbridge/service/job_watch.hpp"

#include "ncbridge/bus/routing.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/service/sha256.hpp"

namespace ncbridge::service {

JobWatch::JobWatch(bus::Participant& participant, std::string job_id)
    : JobWatch(participant, std::vector<std::string>{std::move(job_id)}) {}

JobWatch::JobWatch(bus::Participant& participant, std::vector<std::string> job_ids)
    : pending_(job_ids.begin(), job_ids.end()),
      status_(participant, bus::Topic::Status),
      part21_(participant, bus::Topic::Part21),
      wait_set_(participant),
      delivered_(participant, bus::Topic::Status),
      delivered_over_(participant, bus::Topic::Status, bus::kJobOverPartition) {
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
  return wait_all(timeout, PieceHandler{}, on_over, on_status);
}

std::set<std::string> JobWatch::wait_all(std::chrono::milliseconds timeout, const PieceHandler& on_piece,
                                         const std::function<void(const std::string&, JobOutcome)>& on_over,
                                         const std::function<void(const wire::JobStatus&)>& on_status) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + timeout;
  while (!pending_.empty()) {
    for (const bus::Received& r : status_.take(std::chrono::milliseconds(0), 4096)) {
      if (!r.has_data || !pending_.contains(r.envelope.key)) continue;
      const wire::JobStatus s = wire::decode_status(r.envelope.payload);
      if (on_status) on_status(s);
      if (s.state == wire::JobState::Error || s.state == wire::JobState::Cancelled) {
        pending_.erase(r.envelope.key);
        JobOutcome o;
        o.error = s;
        on_over(r.envelope.key, std::move(o));
      }
    }
    for (const bus::Received& r : part21_.take(std::chrono::milliseconds(0))) {
      if (!r.has_data || !pending_.contains(r.envelope.key)) continue;
      wire::Part21File piece = wire::decode_part21(r.envelope.payload);
      if (piece.job_id != r.envelope.key || sha256(piece.content) != piece.sha256)
        throw InputError({"<part21 file>", 0, 0}, "piece " + std::to_string(piece.seq) + " of the file of job " +
                                                      r.envelope.key + " does not match its SHA-256 digest");
      std::optional<wire::Part21File> file = add_piece(std::move(piece), on_piece);
      if (!file) continue;
      pending_.erase(r.envelope.key);
      incoming_.erase(r.envelope.key);
      say_delivered(r.envelope.key);
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

void JobWatch::say_delivered(const std::string& job_id) {
  wire::JobStatus s;
  s.job_id = job_id;
  s.stage = bus::kStageClient;
  s.state = wire::JobState::Delivered;
  s.progress = 1;
  const std::string bytes = wire::encode_status(s);
  delivered_.write(job_id, bus::kStageClient, 0, static_cast<std::uint32_t>(s.state), true, bytes);
  delivered_over_.write(job_id, bus::kStageClient, 0, static_cast<std::uint32_t>(s.state), true, bytes);
}

std::optional<wire::Part21File> JobWatch::add_piece(wire::Part21File piece, const PieceHandler& on_piece) {
  Incoming& in = incoming_[piece.job_id];
  if (piece.seq < in.next) return std::nullopt;  // a duplicate (a redo by another writer)
  in.ahead.emplace(piece.seq, std::move(piece));
  for (auto it = in.ahead.begin(); it != in.ahead.end() && it->first == in.next; it = in.ahead.erase(it)) {
    ++in.next;
    wire::Part21File& p = it->second;
    if (on_piece) {
      on_piece(p.job_id, p);
      p.content.clear();
      in.file = std::move(p);
    } else if (!in.file) {
      in.file = std::move(p);
    } else {
      in.file->content += p.content;
      in.file->seq = p.seq;
      in.file->more = p.more;
      in.file->sha256 = p.sha256;
    }
    if (!in.file->more) return std::move(in.file);
  }
  return std::nullopt;
}

}  // namespace ncbridge::service
