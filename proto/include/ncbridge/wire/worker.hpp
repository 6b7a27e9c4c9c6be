#pragma once
// A worker's announcement on the ncbridge/workers topic (proto/worker.proto), and its codec.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ncbridge::wire {

struct WorkerInfo {
  std::string stage;
  std::string worker_id;
  std::string host;
  std::uint32_t pid = 0;
  std::int64_t started_unix_ms = 0;
  std::vector<std::string> jobs_in_progress;
  friend bool operator==(const WorkerInfo&, const WorkerInfo&) = default;
};

std::string encode_worker(const WorkerInfo& worker);
WorkerInfo decode_worker(std::string_view bytes);  // throws InputError on malformed bytes

}  // namespace ncbridge::wire
