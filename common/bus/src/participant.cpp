#include "ncbridge/bus/participant.hpp"

#include <utility>

#include "dds_check.hpp"

namespace ncbridge::bus {

Participant::Participant(const BusConfig& config) : domain_id_(config.domain_id) {
  if (!config.cyclonedds_uri.empty()) {
    const dds_entity_t domain = dds_create_domain(config.domain_id, config.cyclonedds_uri.c_str());
    // PRECONDITION_NOT_MET: this process configured the domain already; share it.
    if (domain != DDS_RETCODE_PRECONDITION_NOT_MET) domain_ = detail::check(domain, "dds_create_domain");
  }
  participant_ = dds_create_participant(config.domain_id, nullptr, nullptr);
  if (participant_ < 0) {
    const std::int32_t rc = participant_;
    participant_ = 0;
    reset();
    detail::check(rc, "dds_create_participant");
  }
}

Participant::~Participant() { reset(); }

Participant::Participant(Participant&& other) noexcept
    : domain_(std::exchange(other.domain_, 0)),
      participant_(std::exchange(other.participant_, 0)),
      domain_id_(other.domain_id_) {}

Participant& Participant::operator=(Participant&& other) noexcept {
  if (this != &other) {
    reset();
    domain_ = std::exchange(other.domain_, 0);
    participant_ = std::exchange(other.participant_, 0);
    domain_id_ = other.domain_id_;
  }
  return *this;
}

void Participant::reset() noexcept {
  if (participant_ > 0) dds_delete(participant_);
  if (domain_ > 0) dds_delete(domain_);
  participant_ = 0;
  domain_ = 0;
}

}  // namespace ncbridge::bus
