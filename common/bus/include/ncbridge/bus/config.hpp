#pragma once
// How a process joins the bus: which DDS domain, which Cyclone configuration.
#include <chrono>
#include <cstdint>
#include <string>

namespace ncbridge::bus {

struct BusConfig {
  std::uint32_t domain_id = 0;
  // Cyclone configuration (file URIs "file:///...", or XML text) for this process's domain.
  // Empty: Cyclone reads the CYCLONEDDS_URI environment variable itself, as every Cyclone
  // program does (deploy/cyclonedds/ has the files to point it at).
  std::string cyclonedds_uri;
};

// Domain from NCBRIDGE_DDS_DOMAIN (default 0); configuration left to CYCLONEDDS_URI.
// Throws BusError when NCBRIDGE_DDS_DOMAIN is not a number in 0..230.
BusConfig config_from_environment();

// A Cyclone configuration for runs on one machine: loopback only, multicast on (discovery
// without a peer list, any number of participants), shared memory off, the participant lease
// set to `lease` so a crashed process is noticed that fast, and large datagrams and writer
// buffers (models and Part 21 files are megabytes: deploy/cyclonedds/loopback.xml says why).
std::string loopback_config_xml(std::chrono::milliseconds lease = std::chrono::milliseconds(1000));

}  // namespace ncbridge::bus
