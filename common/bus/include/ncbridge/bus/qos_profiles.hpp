#pragma once
// The QoS of every topic, as plain values: defined in ONE place (src/qos_profiles.cpp), turned
// into Cyclone QoS objects only inside the bus library.
#include <chrono>
#include <cstdint>

#include "ncbridge/bus/topics.hpp"

namespace ncbridge::bus {

enum class Durability : std::uint8_t { Volatile, TransientLocal };
enum class History : std::uint8_t { KeepLast, KeepAll };

struct QosProfile {
  bool reliable = true;
  Durability durability = Durability::Volatile;
  // The writer's history is also what a late reader gets (durability service). Cyclone drops an
  // unregistered instance's samples only from a KeepLast history: job inputs use a deep
  // KeepLast, so a finished job leaves the writer's memory when it is unregistered.
  History history = History::KeepLast;
  std::int32_t depth = 1;                        // per instance
  History reader_history = History::KeepAll;
  std::int32_t reader_depth = 1;                 // KeepLast readers only
  std::int32_t max_instances = -1;               // -1 = unlimited
  std::chrono::milliseconds max_blocking{10'000};  // how long a write may wait for room
  std::chrono::milliseconds liveliness_lease{0};   // 0 = infinite (AUTOMATIC liveliness)
  bool autodispose_unregistered = false;         // a deleted writer disposes its instances
};

QosProfile qos_profile(Topic topic);

}  // namespace ncbridge::bus
