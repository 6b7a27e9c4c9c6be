#pragma once
// Publishes each job of a routed topic (routing.hpp) to the one live worker of the reading stage
// that owns it, and keeps what it wrote of a job until the job is unregistered:
//  - a job is given, when first written, to its rendezvous owner among the stage's live workers
//    (rendezvous.hpp), and stays with it: a worker that joins takes only jobs written after;
//  - when that worker leaves (disposed its announcement, or its lease ran out), the job goes to
//    its owner among the survivors, and everything written of it so far is sent again, in order
//    (the reading stage drops the samples it has already: JobAssembler);
//  - while the stage has no live worker (or in the first `settle` after construction, while the
//    workers are still being discovered), writes are kept and sent when one is there.
// One writer per worker, in that worker's partition (transient-local, as every job input); a
// thread follows the workers topic. Every member may be called from any thread.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/writer.hpp"

namespace ncbridge::bus {

class RoutedWriter final : public SampleWriter {
 public:
  // Throws BusError when `topic` is not routed.
  RoutedWriter(Participant& participant, Topic topic,
               std::chrono::milliseconds settle = std::chrono::milliseconds(300));
  ~RoutedWriter() override;
  RoutedWriter(const RoutedWriter&) = delete;
  RoutedWriter& operator=(const RoutedWriter&) = delete;

  void write(std::string_view key, std::string_view subkey, std::uint64_t seq, std::uint32_t kind, bool last,
             std::string_view payload) override;
  // The job is over: its samples leave this writer (and its worker's durable copy).
  void unregister(std::string_view key, std::string_view subkey) override;
  // Waits until every job is with a worker and every worker acknowledged what it was sent.
  bool wait_for_acks(std::chrono::milliseconds timeout) override;
  // Waits until `count` workers of the reading stage are live and the settle time is over.
  bool wait_for_readers(std::uint32_t count, std::chrono::milliseconds timeout) const;
  Topic topic() const override;

  // The worker a job is with now; nullopt while it waits for one.
  std::optional<std::string> worker_of(std::string_view key, std::string_view subkey = {}) const;
  // How many samples were sent again to a job's new worker.
  std::uint64_t resent() const;
  // Where to say that a job moved to another worker (and any error of the thread that moves
  // them); by default nothing is said. Called on that thread.
  void report_to(std::function<void(const std::string&)> report);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ncbridge::bus
