#pragma once
// The bus a client command joins (submit, status, fetch, cancel, controller-sim, capture): what
// the user said, else what the `ncbridge up` on this machine recorded (up_registry.hpp).
//   domain:        --domain, else NCBRIDGE_DDS_DOMAIN, else the domain of the one `up` running,
//                  else 0 (several `up`s running and none named: a usage error)
//   configuration: CYCLONEDDS_URI, else the configuration of the `up` on that domain, else
//                  Cyclone's default
#include <cstdint>
#include <optional>

#include "ncbridge/bus/config.hpp"
#include "up_registry.hpp"

namespace ncbridge::cli {

struct ClientBus {
  bus::BusConfig config;
  std::optional<UpRecord> up;  // the `up` found on that domain, if any
};

ClientBus client_bus(std::optional<std::uint32_t> domain_option);

// "no interpreter service on DDS domain D (...)": what to say when no service answers.
std::string no_service_message(const ClientBus& bus, std::string_view service);

}  // namespace ncbridge::cli
