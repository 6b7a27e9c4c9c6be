#pragma once
// Flags every service takes (and the environment they default to), logging set-up, and the
// one way a service main runs: parse, join the bus, run the stage until SIGTERM.
#include <functional>
#include <string>

#include "ncbridge/bus/config.hpp"
#include "ncbridge/service/stage_runner.hpp"

namespace CLI { class App; }

namespace ncbridge::service {

struct ServiceOptions {
  bus::BusConfig bus;          // --domain (NCBRIDGE_DDS_DOMAIN), --cyclonedds-uri (CYCLONEDDS_URI)
  RunnerOptions runner;        // --worker-id
  std::string log_level = "info";
};

// Adds --domain, --cyclonedds-uri, --worker-id, --log-level to `app`, defaulting from the
// environment.
void add_service_options(CLI::App& app, ServiceOptions& options);

// Runs a service: `app` (with add_service_options and the stage's own flags) parses argv, then
// `make_spec` builds the stage from the parsed flags, and the stage runs until SIGTERM/SIGINT.
// Returns the exit code: 0 after a clean shutdown, 2 for bad flags, 1 when the bus cannot start.
int run_service(int argc, char** argv, CLI::App& app, ServiceOptions& options,
                const std::function<StageSpec()>& make_spec);

}  // namespace ncbridge::service
