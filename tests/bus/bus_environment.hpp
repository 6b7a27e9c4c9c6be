#pragma once
// Test helper: a DDS domain of this test process's own (derived from its pid, so tests run in
// parallel do not meet) and a loopback Cyclone configuration written to a temporary folder.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "ncbridge/bus/config.hpp"

namespace ncbridge::test {

struct BusEnvironment {
  std::filesystem::path dir;
  std::filesystem::path config_file;
  bus::BusConfig config;

  explicit BusEnvironment(std::chrono::milliseconds lease = std::chrono::milliseconds(1000)) {
    const auto pid = static_cast<std::uint32_t>(getpid());
    dir = std::filesystem::temp_directory_path() / ("ncbridge-bus-test-" + std::to_string(pid));
    std::filesystem::create_directories(dir);
    config_file = dir / "cyclonedds.xml";
    std::ofstream(config_file) << bus::loopback_config_xml(lease);
    config.domain_id = 1 + pid % 200;
    config.cyclonedds_uri = "file://" + config_file.string();
  }
  ~BusEnvironment() {
    std::error_code ignored;
    std::filesystem::remove_all(dir, ignored);
  }
  BusEnvironment(const BusEnvironment&) = delete;
  BusEnvironment& operator=(const BusEnvironment&) = delete;
};

}  // namespace ncbridge::test
