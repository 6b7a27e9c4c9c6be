// `ncbridge up [--workers N] [--detach]`: a local set of services on this machine (loopback DDS):
// N workers of each stage as child processes, until SIGTERM, Ctrl-C or `ncbridge down`, which
// stop them cleanly (SIGTERM, then SIGKILL after a grace period); killed, it takes them with it
// (they get SIGTERM when it dies). The services are the
// ncbridge-* executables beside this one. The bus is --cyclonedds-config's, else CYCLONEDDS_URI's,
// else a loopback configuration with a 1 s lease. Once every stage's workers are live, `up`
// records where it runs (up_registry.hpp), so the other commands of this user find it without
// any export, and says so in one line; then one line per job that ends (done, error, cancelled),
// the services' own logs only from warnings on (-v: everything they say). --detach: the same in
// the background (a session of its own, its output in a log file beside the record); the
// command returns once the services are up.
#include <CLI/CLI.hpp>
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "errors.hpp"
#include "feedback.hpp"
#include "input_files.hpp"
#include "output_files.hpp"
#include "tool_source.hpp"
#include "up_registry.hpp"
#include "ncbridge/bus/config.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/topics.hpp"
#include "ncbridge/bus/worker_tracker.hpp"
#include "ncbridge/service/shutdown_signal.hpp"
#include "ncbridge/wire/status.hpp"

extern char** environ;

namespace ncbridge::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct UpArguments {
  int workers = 1;
  std::optional<std::uint32_t> domain;
  std::string output_dir;
  std::string config;
  std::string live_tools;
  std::string live_tool_table;
  std::string live_tool_table_units = "mm";
  std::string live_stock;
  std::optional<std::string> log_level;
  bool detach = false;
  double start_timeout_s = 60;
  // Passed on to every service (service_options.cpp): how long finished jobs stay on the bus,
  // and how long a job may run in a worker.
  std::optional<std::string> retain_jobs, retain_for, retain_mb, max_job_seconds;
};

struct Child {
  std::string name;
  pid_t pid = 0;
};

constexpr std::array<std::string_view, 4> kStages{bus::kStageInterpreter, bus::kStageCc1Builder,
                                                  bus::kStageFeatureRecognizer, bus::kStageStepWriter};

fs::path own_directory() {
  std::error_code ec;
  const auto exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::current_path() : exe.parent_path();
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
  // The child: our blocked SIGTERM/SIGINT mask lifted, and SIGTERM when this process dies
  // (killed with SIGKILL, it could not stop its services otherwise). Nothing allocated after fork.
  if (access(argv[0], X_OK) != 0) throw std::runtime_error("cannot start " + args[0] + ": " + std::strerror(errno));
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("cannot start " + args[0] + ": " + std::strerror(errno));
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(1);  // died already
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    execve(argv[0], argv.data(), envp.data());
    _exit(127);
  }
  return pid;
}

void stop_all(std::vector<Child>& children) {
  for (const Child& c : children) {
    if (c.pid > 0) kill(c.pid, SIGTERM);
  }
  const auto deadline = Clock::now() + std::chrono::seconds(10);
  for (Child& c : children) {
    while (c.pid > 0) {
      if (waitpid(c.pid, nullptr, WNOHANG) == c.pid) {
        c.pid = 0;
      } else if (Clock::now() > deadline) {
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

// A child that exited: said once, and the run's exit status becomes 1.
bool reap_exited(std::vector<Child>& children) {
  bool any = false;
  for (Child& c : children) {
    int status = 0;
    if (c.pid > 0 && waitpid(c.pid, &status, WNOHANG) == c.pid) {
      print_error(c.name + " (pid " + std::to_string(c.pid) + ") exited (" + (WIFEXITED(status) ? "status " : "signal ") +
                  std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status)) + ")");
      c.pid = 0;
      any = true;
    }
  }
  return any;
}

std::vector<std::string> service_arguments(const UpArguments& args, const std::string& name, const fs::path& bin,
                                           const std::string& log_level) {
  std::vector<std::string> argv{(bin / name).string(), "--log-level", log_level};
  for (const auto& [flag, value] : {std::pair{"--retain-jobs", &args.retain_jobs}, std::pair{"--retain-for", &args.retain_for},
                                    std::pair{"--retain-mb", &args.retain_mb},
                                    std::pair{"--max-job-seconds", &args.max_job_seconds}}) {
    if (*value) argv.insert(argv.end(), {flag, **value});
  }
  if (name == "ncbridge-step-writer" && !args.output_dir.empty()) argv.insert(argv.end(), {"--output-dir", args.output_dir});
  if (name == "ncbridge-interpreter") {
    if (!args.live_tools.empty()) argv.insert(argv.end(), {"--live-tools", fs::absolute(args.live_tools).string()});
    if (!args.live_tool_table.empty()) {
      argv.insert(argv.end(), {"--live-tool-table", fs::absolute(args.live_tool_table).string(), "--live-tool-table-units",
                               args.live_tool_table_units});
    }
    if (!args.live_stock.empty()) argv.insert(argv.end(), {"--live-stock", fs::absolute(args.live_stock).string()});
  }
  return argv;
}

// One line per job that ends, from the status topic, with the local time: done (the step
// writer's), the first error, or cancelled.
class JobLog {
 public:
  void apply(const wire::JobStatus& s) {
    if (s.job_id.empty() || ended_.contains(s.job_id)) return;
    // A client's word (a cancel request) counts for a job a worker has reported on.
    if (s.stage != bus::kStageClient) seen_.insert(s.job_id);
    else if (!seen_.contains(s.job_id)) return;
    std::string what;
    if (s.state == wire::JobState::Done && s.stage == bus::kStageStepWriter) {
      what = "done";
    } else if (s.state == wire::JobState::Cancelled) {
      what = "cancelled";
    } else if (s.state == wire::JobState::Error) {
      const std::string where = s.where.to_string();
      what = "error: " + (where.empty() ? "" : where + ": ") + s.message + " (" + s.stage + ")";
    } else {
      return;
    }
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char time[16];
    std::strftime(time, sizeof time, "%H:%M:%S", &local);
    std::printf("%s %s: %s\n", time, s.job_id.c_str(), what.c_str());
    std::fflush(stdout);
    seen_.erase(s.job_id);
    ended_.insert(s.job_id);
    order_.push_back(s.job_id);
    if (order_.size() > 100'000) {  // bounded on an up that runs for months; a late status of one is harmless
      ended_.erase(order_.front());
      order_.pop_front();
    }
  }

 private:
  std::set<std::string> seen_;   // jobs a worker reported on, not ended
  std::set<std::string> ended_;
  std::deque<std::string> order_;
};

// --detach: the caller waits on `ready` for the line the background `up` writes once its services
// are live (nothing: it failed; its log says why).
int wait_for_detached(pid_t child, int ready, const fs::path& log) {
  std::string said;
  char buffer[512];
  for (ssize_t n; (n = read(ready, buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    said.append(buffer, static_cast<std::size_t>(n));
  }
  close(ready);
  if (!said.empty()) {
    std::fputs(said.c_str(), stdout);
    return exit_status::ok;
  }
  int status = 0;
  waitpid(child, &status, 0);
  std::ifstream in(log);
  std::ostringstream text;
  text << in.rdbuf();
  std::fputs(text.str().c_str(), stderr);
  return WIFEXITED(status) && WEXITSTATUS(status) != 0 ? WEXITSTATUS(status) : exit_status::service_unavailable;
}

int run_up(const UpArguments& args, Verbosity verbosity) {
  if (!args.live_tools.empty()) require_input_file(args.live_tools, "--live-tools");
  if (!args.live_tool_table.empty()) require_input_file(args.live_tool_table, "--live-tool-table");
  if (!args.live_tools.empty() && !args.live_tool_table.empty())
    throw UsageError("--live-tools and --live-tool-table: give one tool list");
  if (!args.live_stock.empty()) require_input_file(args.live_stock, "--live-stock");
  if (!args.config.empty() && !args.config.starts_with("file://") && !args.config.starts_with("<"))
    require_input_file(args.config, "--cyclonedds-config");
  UpArguments run = args;
  if (!run.output_dir.empty()) run.output_dir = fs::absolute(prepare_output_directory(run.output_dir, "--output-dir")).string();
  bus::BusConfig config = bus::config_from_environment();
  if (args.domain) config.domain_id = *args.domain;
  if (const auto running = live_up_record(config.domain_id)) {
    throw UsageError("ncbridge up already runs on DDS domain " + std::to_string(config.domain_id) + " (pid " +
                     std::to_string(running->pid) + "): `ncbridge down` stops it, or give another --domain");
  }
  const fs::path log = up_registry_directory() / ("up-" + std::to_string(config.domain_id) + ".log");
  int ready_pipe = -1;  // --detach: where to say that the services are up
  if (args.detach) {
    fs::create_directories(up_registry_directory());
    fs::permissions(up_registry_directory(), fs::perms::owner_all, fs::perm_options::replace);
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    std::fflush(nullptr);
    const pid_t child = fork();
    if (child < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (child > 0) {
      close(fds[1]);
      return wait_for_detached(child, fds[0], log);
    }
    close(fds[0]);
    ready_pipe = fds[1];
    setsid();
    const int null = open("/dev/null", O_RDONLY);
    const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (null < 0 || out < 0) throw std::runtime_error("cannot open " + log.string() + ": " + std::strerror(errno));
    dup2(null, STDIN_FILENO);
    dup2(out, STDOUT_FILENO);
    dup2(out, STDERR_FILENO);
    close(null);
    close(out);
  }

  service::ShutdownSignal shutdown;
  const fs::path bin = own_directory();
  std::string uri = args.config;
  fs::path generated;  // removed on exit
  if (uri.empty()) {
    if (const char* env_uri = std::getenv("CYCLONEDDS_URI"); env_uri != nullptr && *env_uri != '\0') {
      uri = env_uri;
    } else {
      generated = up_generated_config(config.domain_id);
      fs::create_directories(generated.parent_path());
      fs::permissions(generated.parent_path(), fs::perms::owner_all, fs::perm_options::replace);
      std::ofstream(generated) << bus::loopback_config_xml();
      uri = "file://" + generated.string();
    }
  } else if (!uri.starts_with("file://") && !uri.starts_with("<")) {
    uri = "file://" + fs::absolute(uri).string();
  }
  config.cyclonedds_uri = uri;
  const std::vector<std::string> env{"CYCLONEDDS_URI=" + uri, "NCBRIDGE_DDS_DOMAIN=" + std::to_string(config.domain_id)};
  const std::string log_level = run.log_level ? *run.log_level : verbosity == Verbosity::Verbose ? "info" : "error";

  std::vector<Child> children;
  const auto cleanup = [&] {
    stop_all(children);
    remove_up_record(config.domain_id);
    if (!generated.empty()) fs::remove(generated);
  };
  int exit_code = 0;
  try {
    for (std::string_view stage : kStages) {
      std::string name = "ncbridge-" + std::string(stage);
      std::replace(name.begin(), name.end(), '_', '-');
      for (int i = 1; i <= run.workers; ++i)
        children.push_back({name + "#" + std::to_string(i), spawn(service_arguments(run, name, bin, log_level), env)});
    }
    bus::Participant participant(config);
    bus::Reader workers(participant, bus::Topic::Workers);
    bus::Reader statuses(participant, bus::Topic::Status);
    // Up when every stage has its workers live.
    bus::WorkerTracker tracker;
    const auto deadline = Clock::now() + std::chrono::milliseconds(static_cast<long long>(run.start_timeout_s * 1000));
    for (bool up = false; !up;) {
      for (const bus::Received& r : workers.take(std::chrono::milliseconds(100))) tracker.apply(r);
      up = true;
      for (std::string_view stage : kStages) up = up && tracker.live_workers(stage).size() >= static_cast<std::size_t>(run.workers);
      if (shutdown.requested()) {
        cleanup();
        return exit_status::ok;
      }
      if (reap_exited(children)) throw ServiceUnavailable("a service did not start (its error is above)");
      if (!up && Clock::now() > deadline)
        throw ServiceUnavailable("the services did not all announce themselves within " +
                                 std::to_string(static_cast<long long>(run.start_timeout_s)) + " s");
    }
    UpRecord record;
    record.pid = getpid();
    record.start_time = process_start_time(record.pid).value_or(0);
    record.domain = config.domain_id;
    record.cyclonedds_uri = uri;
    record.output_dir = run.output_dir;
    record.log = args.detach ? log.string() : "";
    record.workers = run.workers;
    write_up_record(record);
    char line[512];
    std::snprintf(line, sizeof line, "ncbridge up: %zu services on DDS domain %u (pid %d%s%s); `ncbridge down` stops them\n",
                  children.size(), config.domain_id, static_cast<int>(record.pid), args.detach ? ", log " : "",
                  args.detach ? log.c_str() : "");
    std::fputs(line, stdout);
    std::fflush(stdout);
    if (ready_pipe >= 0) {
      [[maybe_unused]] const ssize_t n = write(ready_pipe, line, std::strlen(line));
      close(ready_pipe);
      ready_pipe = -1;
    }
    JobLog jobs;
    while (!shutdown.requested()) {
      if (reap_exited(children)) exit_code = 1;
      for (const bus::Received& r : workers.take(std::chrono::milliseconds(0))) tracker.apply(r);
      for (const bus::Received& r : statuses.take(std::chrono::milliseconds(100), 4096)) {
        if (!r.has_data || r.envelope.key.empty()) continue;
        try {
          jobs.apply(wire::decode_status(r.envelope.payload));
        } catch (const InputError&) {
        }
      }
    }
  } catch (...) {
    cleanup();
    throw;
  }
  cleanup();
  return exit_code;
}

}  // namespace

void add_up_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<UpArguments>();
  CLI::App* cmd = app.add_subcommand("up", "Run a local set of the DDS services (loopback) until `ncbridge down`, Ctrl-C or SIGTERM");
  cmd->add_option("--workers", args->workers, "Workers per stage")->check(CLI::Range(1, 16));
  cmd->add_option("--domain", args->domain, "DDS domain id (default: NCBRIDGE_DDS_DOMAIN, else 0)")->check(CLI::Range(0, 230));
  cmd->add_option("--cyclonedds-config", args->config, "Cyclone configuration file (default: CYCLONEDDS_URI, else loopback, 1 s lease)");
  cmd->add_flag("-d,--detach", args->detach, "Run in the background; return once the services are up (log beside the record)");
  cmd->add_option("--output-dir", args->output_dir, "The step writers also write each file here (created when missing)");
  cmd->add_option("--live-tools", args->live_tools, "Tool list for live-capture runs (controller-sim, capture)");
  cmd->add_option("--live-tool-table", args->live_tool_table, "LinuxCNC tool table (.tbl) for live-capture runs, instead of --live-tools");
  cmd->add_option("--live-tool-table-units", args->live_tool_table_units, "Units of the tool table values (default mm)")
      ->check(CLI::IsMember({"mm", "inch"}));
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
  cmd->add_option("--start-timeout", args->start_timeout_s, "Seconds the services have to come up (default 60)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--log-level", args->log_level, "Services' log level (default error: up says one line per job; -v: info)")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}));
  cmd->callback([args, cmd, &exit_code]() { exit_code = run_up(*args, verbosity_of(*cmd)); });
}

}  // namespace ncbridge::cli
