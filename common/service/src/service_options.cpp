#include "ncbridge/service/service_options.hpp"

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <cstdlib>
#include <exception>

#include "ncbridge/bus/participant.hpp"
#include "ncbridge/service/shutdown_signal.hpp"

namespace ncbridge::service {

void add_service_options(CLI::App& app, ServiceOptions& options) {
  app.add_option("--domain", options.bus.domain_id, "DDS domain id (default: NCBRIDGE_DDS_DOMAIN, else 0)")
      ->check(CLI::Range(0, 230));
  app.add_option("--cyclonedds-uri", options.bus.cyclonedds_uri,
                 "Cyclone DDS configuration, file:///... (default: CYCLONEDDS_URI)");
  app.add_option("--worker-id", options.runner.worker_id, "Worker id on the workers topic (default: host/pid)");
  app.add_option("--retain-jobs", options.runner.retention.max_jobs,
                 "Jobs over whose statuses and results stay on the bus (default 1000; the oldest leave first)");
  app.add_option_function<double>(
         "--retain-for", [&options](double s) { options.runner.retention.max_age = std::chrono::seconds(static_cast<long long>(s)); },
         "Seconds a job's statuses and results stay on the bus after it is over (default 3600)")
      ->check(CLI::NonNegativeNumber);
  app.add_option_function<double>(
         "--retain-mb", [&options](double mb) { options.runner.retention.max_result_bytes = static_cast<std::uint64_t>(mb * 1048576.0); },
         "Megabytes of final results (Part 21 files) kept on the bus (default 1024)")
      ->check(CLI::NonNegativeNumber);
  app.add_option_function<double>(
         "--max-job-seconds",
         [&options](double s) { options.runner.max_job_time = std::chrono::milliseconds(static_cast<long long>(s * 1000.0)); },
         "Longest a job may run in this worker before it is stopped with an error (default 600; 0: no limit)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--log-level", options.log_level, "trace, debug, info, warn, error")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}));
}

int run_service(int argc, char** argv, CLI::App& app, ServiceOptions& options,
                const std::function<StageSpec()>& make_spec) {
  try {
    options.bus = bus::config_from_environment();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    ShutdownSignal shutdown;  // before DDS starts its threads, so they inherit the blocked mask
    StageSpec spec = make_spec();
    auto logger = spdlog::stderr_color_st(spec.stage);
    logger->set_pattern("%Y-%m-%dT%H:%M:%S.%e %n[%P] %l: %v");
    logger->set_level(spdlog::level::from_str(options.log_level));
    spdlog::set_default_logger(logger);
    bus::Participant participant(options.bus);
    StageRunner runner(participant, std::move(spec), options.runner);
    return runner.run(shutdown);
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
}

}  // namespace ncbridge::service
