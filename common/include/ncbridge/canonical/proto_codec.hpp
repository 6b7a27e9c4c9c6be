#pragma once
// The canonical call stream on the wire: batches of calls as proto/canonical.proto
// CanonicalBatch bytes (one sample of the ncbridge/canonical topic). Lossless: decoding an
// encoded batch gives back every field of every call, bit for bit.
//
// Implemented in proto/ (library ncbridge::proto); no generated header leaks from here.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/canonical/call.hpp"

namespace ncbridge::canonical {

// A program file of the stream (Sink::source_file): calls refer to it by index.
struct SourceFile {
  std::uint32_t index = 0;
  std::string path;
  friend bool operator==(const SourceFile&, const SourceFile&) = default;
};

// What to encode, without copying the calls.
struct CanonicalBatchView {
  std::string_view job_id;
  std::uint64_t seq = 0;                  // 0, 1, 2, ... within the job
  std::span<const SourceFile> files;      // announced before the calls of this batch
  std::span<const Call> calls;
  bool last = false;                      // the job's last batch (may hold no calls)
};

struct DecodedBatch {
  std::string job_id;
  std::uint64_t seq = 0;
  std::vector<SourceFile> files;
  std::vector<Call> calls;
  bool last = false;
};

std::string encode_batch(const CanonicalBatchView& batch);

// Throws ncbridge::InputError (file "<canonical batch>", no line) when the bytes are not a
// CanonicalBatch: truncated, malformed, a call with no data, an enum or integer out of range.
DecodedBatch decode_batch(std::string_view bytes);

// Replays a decoded batch into a sink: source_file for each file, then each call. end() is
// not called (the consumer calls it after the last batch).
void replay(const DecodedBatch& batch, Sink& sink);

}  // namespace ncbridge::canonical
