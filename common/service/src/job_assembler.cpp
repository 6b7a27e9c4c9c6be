#include "ncbridge/service/job_assembler.hpp"

#include <algorithm>

namespace ncbridge::service {

bool JobAssembler::add(bus::Topic topic, const std::string& job_id, const bus::Envelope& sample) {
  if (finished_.contains(job_id)) return false;
  auto [it, fresh] = jobs_.try_emplace(job_id);
  Pending& p = it->second;
  if (fresh) {
    p.input.topic = topic;
    p.input.job_id = job_id;
    p.input.subkey = sample.subkey;
  }
  if (p.complete || p.samples.contains(sample.seq)) return false;
  p.samples.emplace(sample.seq, sample);
  if (sample.last) p.last_seq = sample.seq;
  if (!p.last_seq || p.samples.size() != *p.last_seq + 1 || p.samples.rbegin()->first != *p.last_seq) return false;
  p.complete = true;
  p.completed_order = ++completions_;
  for (auto& [seq, envelope] : p.samples) {
    p.input.payloads.push_back(std::move(envelope.payload));
    p.input.kinds.push_back(envelope.kind);
  }
  p.samples.clear();
  return true;
}

const JobInput* JobAssembler::complete(std::string_view job_id) const {
  const auto it = jobs_.find(job_id);
  return it != jobs_.end() && it->second.complete ? &it->second.input : nullptr;
}

std::vector<std::string> JobAssembler::complete_jobs() const {
  std::vector<std::pair<std::uint64_t, std::string>> order;
  for (const auto& [id, p] : jobs_) {
    if (p.complete) order.emplace_back(p.completed_order, id);
  }
  std::sort(order.begin(), order.end());
  std::vector<std::string> out;
  out.reserve(order.size());
  for (auto& [n, id] : order) out.push_back(std::move(id));
  return out;
}

bool JobAssembler::known(std::string_view job_id) const { return jobs_.contains(job_id); }

void JobAssembler::finish(const std::string& job_id) {
  jobs_.erase(job_id);
  finished_.insert(job_id);
}

}  // namespace ncbridge::service
