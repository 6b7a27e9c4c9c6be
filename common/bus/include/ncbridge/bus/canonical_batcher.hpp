#pragma once
// A canonical::Sink that packs the call stream of one job into CanonicalBatch envelopes for
// the ncbridge/canonical topic (key = job_id, seq 0, 1, ...; the last one marked), handing
// each to `publish` (a Writer in a service, a vector in a test).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "ncbridge/bus/envelope.hpp"
#include "ncbridge/canonical/call.hpp"
#include "ncbridge/canonical/proto_codec.hpp"

namespace ncbridge::bus {

class CanonicalBatcher : public canonical::Sink {
 public:
  using Publish = std::function<void(const Envelope&)>;
  CanonicalBatcher(std::string job_id, std::size_t calls_per_batch, Publish publish);

  void source_file(std::uint32_t index, std::string_view path) override;
  void call(const canonical::Call& call) override;
  void end() override;  // publishes the remaining calls as the last batch (possibly empty)

  std::uint64_t batches_published() const { return seq_; }

 private:
  void flush(bool last);
  std::string job_id_;
  std::size_t calls_per_batch_;
  Publish publish_;
  std::vector<canonical::SourceFile> files_;
  std::vector<canonical::Call> calls_;
  std::uint64_t seq_ = 0;
  bool ended_ = false;
};

}  // namespace ncbridge::bus
