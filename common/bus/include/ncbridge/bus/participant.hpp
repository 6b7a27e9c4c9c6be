#pragma once
// A process's membership of a DDS domain (RAII): the domain (when this process configures it)
// and one participant. Writers and readers are made from it and must not outlive it.
// One Participant per domain per process: a second one in the same process reuses the first's
// domain configuration.
#include <cstdint>

#include "ncbridge/bus/config.hpp"

namespace ncbridge::bus {

class Participant {
 public:
  explicit Participant(const BusConfig& config);  // throws BusError
  ~Participant();
  Participant(Participant&& other) noexcept;
  Participant& operator=(Participant&& other) noexcept;
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  std::int32_t handle() const { return participant_; }  // dds_entity_t
  std::uint32_t domain_id() const { return domain_id_; }

 private:
  void reset() noexcept;
  std::int32_t domain_ = 0;       // 0 when the domain was made by someone else (env config)
  std::int32_t participant_ = 0;
  std::uint32_t domain_id_ = 0;
};

}  // namespace ncbridge::bus
