#pragma once
// Subscribes to one topic with that topic's QoS profile (RAII). take() waits on a waitset with
// a timeout: it never blocks for longer than asked.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "ncbridge/bus/envelope.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/topics.hpp"

namespace ncbridge::bus {

class Reader {
 public:
  // `partition`: empty for the default partition (what a Writer made without one publishes in).
  Reader(Participant& participant, Topic topic, std::string_view partition = {});  // throws BusError
  ~Reader();
  Reader(Reader&& other) noexcept;
  Reader& operator=(Reader&& other) noexcept;
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  // Takes up to `max` samples and instance-state changes, in arrival order per instance.
  // Returns at once if any are there, else waits up to `timeout`; empty when none came.
  std::vector<Received> take(std::chrono::milliseconds timeout, std::size_t max = 256);

  // Waits until at least `count` writers are matched; false on timeout.
  bool wait_for_writers(std::uint32_t count, std::chrono::milliseconds timeout) const;

  Topic topic() const { return topic_; }
  // The read condition (any sample state), for a bus::WaitSet.
  std::int32_t read_condition() const { return condition_; }

 private:
  std::size_t take_now(std::vector<Received>& out, std::size_t max);
  void reset() noexcept;
  std::int32_t subscriber_ = 0;  // only with a partition
  std::int32_t topic_entity_ = 0;
  std::int32_t reader_ = 0;
  std::int32_t waitset_ = 0;
  std::int32_t condition_ = 0;
  Topic topic_ = Topic::Programs;
};

}  // namespace ncbridge::bus
