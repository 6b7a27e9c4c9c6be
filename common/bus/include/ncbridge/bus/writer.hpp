#pragma once
// Publishes envelopes on one topic with that topic's QoS profile (RAII: deleting the writer
// unregisters its instances; on the workers topic that disposes them).
#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

#include "ncbridge/bus/envelope.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/topics.hpp"

namespace ncbridge::bus {

// What a job's publisher needs of a writer: a plain Writer, or a RoutedWriter that sends each
// job to the worker that owns it (routed_writer.hpp).
class SampleWriter {
 public:
  virtual ~SampleWriter() = default;
  virtual void write(std::string_view key, std::string_view subkey, std::uint64_t seq, std::uint32_t kind, bool last,
                     std::string_view payload) = 0;
  virtual void unregister(std::string_view key, std::string_view subkey) = 0;
  virtual bool wait_for_acks(std::chrono::milliseconds timeout) = 0;
  virtual Topic topic() const = 0;
};

class Writer final : public SampleWriter {
 public:
  // `partition`: empty for the default partition, which every reader made without one reads.
  Writer(Participant& participant, Topic topic, std::string_view partition = {});  // throws BusError
  ~Writer() override;
  Writer(Writer&& other) noexcept;
  Writer& operator=(Writer&& other) noexcept;
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  // Blocks while the topic's resource limits or flow control say so, at most the profile's
  // max_blocking; throws BusError when that runs out.
  void write(const Envelope& sample);
  void write(std::string_view key, std::string_view subkey, std::uint64_t seq, std::uint32_t kind, bool last,
             std::string_view payload) override;

  // The instance (key, subkey) is finished: its samples leave this writer's durable history.
  void unregister(std::string_view key, std::string_view subkey) override;
  // The instance is withdrawn: readers see InstanceState::Disposed.
  void dispose(std::string_view key, std::string_view subkey);

  // Waits until every matched reader has acknowledged everything written; false on timeout.
  bool wait_for_acks(std::chrono::milliseconds timeout) override;
  // Number of readers currently matched.
  std::uint32_t matched_readers() const;
  // Waits until at least `count` readers are matched; false on timeout.
  bool wait_for_readers(std::uint32_t count, std::chrono::milliseconds timeout) const;

  Topic topic() const override { return topic_; }

 private:
  void reset() noexcept;
  std::int32_t publisher_ = 0;  // only with a partition
  std::int32_t topic_entity_ = 0;
  std::int32_t writer_ = 0;
  Topic topic_ = Topic::Programs;
};

}  // namespace ncbridge::bus
