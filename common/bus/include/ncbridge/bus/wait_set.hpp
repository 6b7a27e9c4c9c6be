#pragma once
// Waits for data on any of several readers at once (RAII), so a service loop sleeps until
// something comes instead of polling each reader in turn.
#include <chrono>
#include <cstdint>

#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/reader.hpp"

namespace ncbridge::bus {

class WaitSet {
 public:
  explicit WaitSet(Participant& participant);  // throws BusError
  ~WaitSet();
  WaitSet(const WaitSet&) = delete;
  WaitSet& operator=(const WaitSet&) = delete;

  // The reader must outlive this wait set (or be attached no more).
  void attach(const Reader& reader);
  // Returns true as soon as an attached reader has something to take (or wake() was called),
  // false after `timeout`.
  bool wait(std::chrono::milliseconds timeout);
  // Ends a wait now, from any thread (or the next one, if none is under way).
  void wake();

 private:
  std::int32_t waitset_ = 0;
  std::int32_t guard_ = 0;
};

}  // namespace ncbridge::bus
