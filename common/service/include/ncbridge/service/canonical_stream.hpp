#pragma once
// How a job's canonical stream is laid out on the ncbridge/canonical topic by the interpreter
// service: seq 0 is the job's context (kind kJobContext, payload: the proto Job without its
// program text: tools, stock, level, output name, which the cc1_builder needs), then the
// CanonicalBatch samples (kind kCanonicalBatch) as seq 1, 2, ..., the last one marked.
#include <cstdint>

namespace ncbridge::service {

inline constexpr std::uint32_t kCanonicalBatch = 0;
inline constexpr std::uint32_t kJobContext = 1;

}  // namespace ncbridge::service
