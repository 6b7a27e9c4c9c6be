// `ncbridge up [--workers N]`: a local set of services on this machine (loopback DDS): N workers
// of each stage as child processes, until SIGTERM or Ctrl-C, which stops them cleanly (SIGTERM,
// then SIGKILL after a grace period). The services are the ncbridge-* executables beside this
// one. The bus is CYCLONEDDS_URI's (else a loopback configuration with a 1 s lease). It prints the environment a `submit` in another shell needs.
#include <CLI/CLI.hpp>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "errors.hpp"
#include "input_files.hpp"
#include "output_files.hpp"
#include "ncbridge/bus/config.hpp"
#include "ncbridge/service/shutdown_signal.hpp"

extern char** environ;

namespace ncbridge::cli {
namespace {

struct UpArguments {
  int workers = 1;
  std::optional<std::uint32_t> domain;
  std::string output_dir;
  std::string config;
  std::string live_tools;
  std::string live_stock;
  std::string log_level = "info";
  // Passed on to every service (service_options.cpp): how long finished jobs stay on the bus,
  // and how long a job may run in a worker.
  std::optional<std::string> retain_jobs, retain_for, retain_mb, max_job_seconds;
};

struct Child {
  std::string name;
  pid_t pid = 0;
};

std::filesystem::path own_directory() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::current_path() : exe.parent_path();
}

pid_t spawn(const std::vector<std::string>& args, const std::vector<std::string>& extra_env) {
  std::vector<std::string> env_store(extra_env);
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry(*e);
    bool overridden = false;
    for (const std::string& x : extra_env) overridden = overridden || entry.starts_with(x.substr(0, x.find('=') + 1));
    if (!overridden) env_store.push_back(entry);
  }
  std::vector<char*> argv;
  std::vector<char*> envp;
  std::vector<std::string> args_store(args);
  for (std::string& a : args_store) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (std::string& e : env_store) envp.push_back(e.data());
  envp.push_back(nullptr);
  // The children must not inherit our blocked SIGTERM/SIGINT mask.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0], nullptr, &attr, argv.data(), envp.data());
  posix_spawnattr_destroy(&attr);
  if (rc != 0) throw std::runtime_error("cannot start " + args[0] + ": " + std::strerror(rc));
  return pid;
}

void stop_all(std::vector<Child>& children) {
  for (const Child& c : children) kill(c.pid, SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  for (Child& c : children) {
    while (c.pid > 0) {
      if (waitpid(c.pid, nullptr, WNOHANG) == c.pid) {
        c.pid = 0;
      } else if (std::chrono::steady_clock::now() > deadline) {
        print_warning({}, c.name + " did not stop, killing it");
        kill(c.pid, SIGKILL);
        waitpid(c.pid, nullptr, 0);
        c.pid = 0;
      } else {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    }
  }
}

int run_up(const UpArguments& args) {
  if (!args.live_tools.empty()) require_input_file(args.live_tools, "--live-tools");
  if (!args.live_stock.empty()) require_input_file(args.live_stock, "--live-stock");
  if (!args.config.empty() && !args.config.starts_with("file://") && !args.config.starts_with("<"))
    require_input_file(args.config, "--cyclonedds-config");
  if (!args.output_dir.empty()) prepare_output_directory(args.output_dir, "--output-dir");
  service::ShutdownSignal shutdown;
  const std::filesystem::path bin = own_directory();
  bus::BusConfig config = bus::config_from_environment();
  if (args.domain) config.domain_id = *args.domain;
  std::string uri = args.config;
  std::filesystem::path generated;  // removed on exit
  if (uri.empty()) {
    if (const char* env_uri = std::getenv("CYCLONEDDS_URI"); env_uri != nullptr && *env_uri != '\0') {
      uri = env_uri;
    } else {
      generated = std::filesystem::temp_directory_path() / ("ncbridge-up-" + std::to_string(getpid()) + ".xml");
      std::ofstream(generated) << bus::loopback_config_xml();
      uri = "file://" + generated.string();
    }
  } else if (!uri.starts_with("file://") && !uri.starts_with("<")) {
    uri = "file://" + std::filesystem::absolute(uri).string();
  }
  const std::vector<std::string> env{"CYCLONEDDS_URI=" + uri, "NCBRIDGE_DDS_DOMAIN=" + std::to_string(config.domain_id)};

  std::vector<Child> children;
  try {
    for (const char* stage : {"interpreter", "cc1-builder", "feature-recognizer", "step-writer"}) {
      for (int i = 1; i <= args.workers; ++i) {
        const std::string name = std::string("ncbridge-") + stage;
        std::vector<std::string> argv{(bin / name).string(), "--log-level", args.log_level};
        for (const auto& [flag, value] : {std::pair{"--retain-jobs", &args.retain_jobs},
                                          std::pair{"--retain-for", &args.retain_for},
                                          std::pair{"--retain-mb", &args.retain_mb},
                                          std::pair{"--max-job-seconds", &args.max_job_seconds}}) {
          if (*value) argv.insert(argv.end(), {flag, **value});
        }
        if (name == "ncbridge-step-writer" && !args.output_dir.empty()) {
          argv.insert(argv.end(), {"--output-dir", args.output_dir});
        }
        if (name == "ncbridge-interpreter") {
          if (!args.live_tools.empty()) argv.insert(argv.end(), {"--live-tools", args.live_tools});
          if (!args.live_stock.empty()) argv.insert(argv.end(), {"--live-stock", args.live_stock});
        }
        children.push_back({name + "#" + std::to_string(i), spawn(argv, env)});
      }
    }
  } catch (...) {
    stop_all(children);
    throw;
  }
  std::printf("ncbridge up: %zu services on DDS domain %u. In another shell:\n  export %s %s\n",
              children.size(), config.domain_id, env[0].c_str(), env[1].c_str());
  std::fflush(stdout);
  int exit_code = 0;
  while (!shutdown.requested()) {
    for (Child& c : children) {
      int status = 0;
      if (c.pid > 0 && waitpid(c.pid, &status, WNOHANG) == c.pid) {
        print_error(c.name + " (pid " + std::to_string(c.pid) + ") exited (" + (WIFEXITED(status) ? "status " : "signal ") +
                    std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status)) + ")");
        c.pid = 0;
        exit_code = 1;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  stop_all(children);
  if (!generated.empty()) std::filesystem::remove(generated);
  return exit_code;
}

}  // namespace

void add_up_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<UpArguments>();
  CLI::App* cmd = app.add_subcommand("up", "Run a local set of the DDS services (loopback) until Ctrl-C or SIGTERM");
  cmd->add_option("--workers", args->workers, "Workers per stage")->check(CLI::Range(1, 16));
  cmd->add_option("--domain", args->domain, "DDS domain id (default: NCBRIDGE_DDS_DOMAIN, else 0)")->check(CLI::Range(0, 230));
  cmd->add_option("--cyclonedds-config", args->config, "Cyclone configuration file (default: loopback, 1 s lease)");
  cmd->add_option("--output-dir", args->output_dir, "The step writers also write each file here (created when missing)");
  cmd->add_option("--live-tools", args->live_tools, "Tool list for live-capture runs (controller-sim)");
  cmd->add_option("--live-stock", args->live_stock, "Stock for live-capture runs");
  cmd->add_option("--retain-jobs", args->retain_jobs, "Each worker keeps its last N finished jobs on the bus (default 1000)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--retain-for", args->retain_for, "... and none older than this many seconds (default 3600)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--retain-mb", args->retain_mb, "... and step writers at most this many MB of results (default 1024)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-job-seconds", args->max_job_seconds,
                  "Longest a job may run in a worker before it is stopped with an error (default 600; 0: no limit)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--log-level", args->log_level, "Services' log level")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}));
  cmd->callback([args, &exit_code]() { exit_code = run_up(*args); });
}

}  // namespace ncbridge::cli
