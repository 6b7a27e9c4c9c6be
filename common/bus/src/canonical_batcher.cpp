#include "ncbridge/bus/canonical_batcher.hpp"

#include <stdexcept>

namespace ncbridge::bus {

CanonicalBatcher::CanonicalBatcher(std::string job_id, std::size_t calls_per_batch, Publish publish)
    : job_id_(std::move(job_id)), calls_per_batch_(calls_per_batch == 0 ? 1 : calls_per_batch), publish_(std::move(publish)) {
  calls_.reserve(calls_per_batch_);
}

void CanonicalBatcher::source_file(std::uint32_t index, std::string_view path) {
  files_.push_back({index, std::string(path)});
}

void CanonicalBatcher::call(const canonical::Call& call) {
  if (ended_) throw std::logic_error("CanonicalBatcher: call after end()");
  calls_.push_back(call);
  if (calls_.size() >= calls_per_batch_) flush(false);
}

void CanonicalBatcher::end() {
  if (ended_) return;
  flush(true);
  ended_ = true;
}

void CanonicalBatcher::flush(bool last) {
  Envelope e;
  e.key = job_id_;
  e.seq = seq_;
  e.last = last;
  e.payload = canonical::encode_batch({job_id_, seq_, files_, calls_, last});
  publish_(e);
  ++seq_;
  files_.clear();
  calls_.clear();
}

}  // namespace ncbridge::bus
