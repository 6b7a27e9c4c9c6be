#include "ncbridge/service/job_assembler.hpp"

#include <algorithm>

namespace ncbridge::service {

bool JobAssembler::add(bus::Topic topic, const std::string& job_id, const bus::Envelope& sample) {
  if (finished_.contains(job_id)) return false;
  auto [it, fresh] = jobs_.try_emplace(job_id);
  Pending& p = it->second;
  if (fresh) {
    p.key = {topic, job_id, sample.subkey};
    p.arrival = ++arrivals_;
  }
  if (sample.seq < p.next || p.samples.contains(sample.seq)) return false;
  if (p.last_seq && sample.seq > *p.last_seq) return false;  // beyond the end: not of this stream
  p.samples.emplace(sample.seq, sample);
  if (sample.last) p.last_seq = sample.seq;
  return true;
}

std::vector<std::string> JobAssembler::jobs() const {
  std::vector<std::pair<std::uint64_t, std::string>> order;
  order.reserve(jobs_.size());
  for (const auto& [id, p] : jobs_) order.emplace_back(p.arrival, id);
  std::sort(order.begin(), order.end());
  std::vector<std::string> out;
  out.reserve(order.size());
  for (auto& [n, id] : order) out.push_back(std::move(id));
  return out;
}

const JobKey* JobAssembler::key(std::string_view job_id) const {
  const auto it = jobs_.find(job_id);
  return it == jobs_.end() ? nullptr : &it->second.key;
}

bool JobAssembler::ready(std::string_view job_id) const {
  const auto it = jobs_.find(job_id);
  return it != jobs_.end() && it->second.samples.contains(it->second.next);
}

std::vector<bus::Envelope> JobAssembler::take_ready(std::string_view job_id) {
  std::vector<bus::Envelope> out;
  const auto it = jobs_.find(job_id);
  if (it == jobs_.end()) return out;
  Pending& p = it->second;
  for (auto s = p.samples.begin(); s != p.samples.end() && s->first == p.next; s = p.samples.erase(s)) {
    out.push_back(std::move(s->second));
    ++p.next;
  }
  return out;
}

bool JobAssembler::taken_all(std::string_view job_id) const {
  const auto it = jobs_.find(job_id);
  return it != jobs_.end() && it->second.last_seq && it->second.next > *it->second.last_seq;
}

bool JobAssembler::complete(std::string_view job_id) const {
  const auto it = jobs_.find(job_id);
  if (it == jobs_.end() || !it->second.last_seq) return false;
  const Pending& p = it->second;
  return p.samples.size() == *p.last_seq + 1 - p.next &&
         (p.samples.empty() || (p.samples.begin()->first == p.next && p.samples.rbegin()->first == *p.last_seq));
}

void JobAssembler::finish(const std::string& job_id) {
  jobs_.erase(job_id);
  if (!finished_.insert(job_id).second) return;
  finished_order_.push_back(job_id);
  while (finished_order_.size() > remembered_finished_) {
    finished_.erase(finished_order_.front());
    finished_order_.pop_front();
  }
}

}  // namespace ncbridge::service
