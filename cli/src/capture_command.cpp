// `ncbridge capture linuxcnc|mtconnect`: live capture from a real controller. An adapter
// watches what the controller executes and publishes each run on the blocks topic: RUN_START
// (the program's path, its text and the controller's tool table), every block as it executes,
// RUN_END (marked aborted when the run stopped before the program's end). The interpreter
// service turns each run into job "<controller>/<run>" (docs/deployment.md, "Live capture").
//
//   linuxcnc: runs the compiled-in status reader (services/capture/linuxcnc_status.py) with the
//             controller's Python, beside the controller, as its user.
//   mtconnect: polls an agent's /current, then /sample?from=NEXT, for one device.
#include <CLI/CLI.hpp>
#include <curl/curl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "client_bus.hpp"
#include "commands.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/writer.hpp"
#include "ncbridge/capture/execution_order.hpp"
#include "ncbridge/capture/linuxcnc_status.hpp"
#include "ncbridge/capture/mtconnect_run.hpp"
#include "ncbridge/capture/mtconnect_streams.hpp"
#include "ncbridge/capture/run_tracker.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/wire/block.hpp"

extern char** environ;

namespace ncbridge::cli {
namespace {

using Clock = std::chrono::steady_clock;

std::atomic<bool> g_stop{false};
extern "C" void on_stop_signal(int) { g_stop = true; }

struct CaptureArguments {
  std::string controller;
  std::optional<std::uint32_t> domain;
  int runs = 0;                // stop after this many runs ended (0 = never)
  // linuxcnc
  double poll_ms = 5;
  std::string python = "/usr/bin/python3";  // the Python LinuxCNC's Debian package installs its module for
  // mtconnect
  std::string agent;
  std::string device;
  std::string program_dir;
  std::string dialect = "rs274ngc";
  double interval_ms = 200;
  int count = 1000;
};

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string now_run_id() {
  return "run-" + std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(
                                     std::chrono::system_clock::now().time_since_epoch()).count());
}

// Publishes a tracker's events on the blocks topic, one DDS instance per run.
class RunPublisher {
 public:
  RunPublisher(bus::Participant& participant, std::string controller)
      : writer_(participant, bus::Topic::Blocks), controller_(std::move(controller)) {}

  // Returns the number of runs that ended.
  int publish(const std::vector<capture::RunEvent>& events) {
    int ended = 0;
    for (const capture::RunEvent& e : events) {
      wire::ExecutedBlock b;
      b.controller_id = controller_;
      if (e.kind == capture::RunEvent::Kind::Start) {
        forget_finished_runs();
        run_id_ = now_run_id();
        seq_ = 0;
        b.kind = wire::BlockKind::RunStart;
        b.program_text = e.program_text;
        b.tool_table = e.tool_table;
        b.tool_table_inch = e.tool_table_inch;
        b.start_line = e.start_line;
        std::fprintf(stderr, "ncbridge capture: run %s/%s started: %s%s\n", controller_.c_str(), run_id_.c_str(),
                     e.text.c_str(), e.start_line ? (" from line " + std::to_string(e.start_line)).c_str() : "");
      } else if (e.kind == capture::RunEvent::Kind::Block) {
        b.kind = wire::BlockKind::Block;
        b.line = e.line;
      } else {
        b.kind = wire::BlockKind::RunEnd;
        b.aborted = e.aborted;
        b.reason = e.reason;
        ++ended;
        if (e.aborted) {
          std::fprintf(stderr, "ncbridge capture: run %s/%s ABORTED after %llu blocks: %s\n", controller_.c_str(),
                       run_id_.c_str(), static_cast<unsigned long long>(e.blocks), e.reason.c_str());
        } else {
          std::fprintf(stderr, "ncbridge capture: run %s/%s completed: %llu blocks\n", controller_.c_str(),
                       run_id_.c_str(), static_cast<unsigned long long>(e.blocks));
        }
      }
      b.run_id = run_id_;
      b.seq = seq_;
      b.text = e.text;
      writer_.write(controller_, run_id_, seq_, static_cast<std::uint32_t>(b.kind), b.kind == wire::BlockKind::RunEnd,
                    wire::encode_block(b));
      ++seq_;
      if (b.kind == wire::BlockKind::RunEnd) finished_.push_back(run_id_);
    }
    return ended;
  }

  // Waits (at most `timeout`) until the services have every published block.
  void drain(std::chrono::milliseconds timeout) { writer_.wait_for_acks(timeout); }

 private:
  // A finished run the services have taken leaves the writer's durable history, so a capture
  // that runs for months holds one run at a time, not every run.
  void forget_finished_runs() {
    if (finished_.empty() || !writer_.wait_for_acks(std::chrono::milliseconds(0))) return;
    for (const std::string& run : finished_) writer_.unregister(controller_, run);
    finished_.clear();
  }

  bus::Writer writer_;
  std::string controller_;
  std::string run_id_;
  std::uint64_t seq_ = 0;
  std::vector<std::string> finished_;
};

// ---- LinuxCNC

// The status reader as a child process; its standard output, line by line.
class StatusReaderProcess {
 public:
  StatusReaderProcess(const std::string& python, double poll_ms) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("cannot create a pipe");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    const std::string script(capture::linuxcnc_status_script());
    const std::string period = std::to_string(poll_ms / 1000.0);
    std::vector<std::string> args = {python, "-u", "-c", script, period};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int rc = posix_spawnp(&pid_, python.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (rc != 0) {
      ::close(fds[0]);
      throw std::runtime_error("cannot start " + python + " for the LinuxCNC status reader");
    }
    fd_ = fds[0];
  }
  ~StatusReaderProcess() {
    if (fd_ >= 0) ::close(fd_);
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  StatusReaderProcess(const StatusReaderProcess&) = delete;
  StatusReaderProcess& operator=(const StatusReaderProcess&) = delete;

  // The next complete line; nullopt when none came within `timeout`; throws when the reader ended.
  std::optional<std::string> next_line(std::chrono::milliseconds timeout) {
    for (;;) {
      const std::size_t nl = buffer_.find('\n');
      if (nl != std::string::npos) {
        std::string line = buffer_.substr(0, nl);
        buffer_.erase(0, nl + 1);
        return line;
      }
      pollfd p{fd_, POLLIN, 0};
      const int ready = ::poll(&p, 1, static_cast<int>(timeout.count()));
      if (ready == 0) return std::nullopt;
      if (ready < 0) {
        if (errno == EINTR) return std::nullopt;
        throw std::runtime_error("cannot read the LinuxCNC status reader");
      }
      char chunk[4096];
      const ssize_t n = ::read(fd_, chunk, sizeof chunk);
      if (n <= 0) throw std::runtime_error("the LinuxCNC status reader ended");
      buffer_.append(chunk, static_cast<std::size_t>(n));
    }
  }

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string buffer_;
};

int run_capture_linuxcnc(const CaptureArguments& args) {
  const bus::BusConfig config = client_bus(args.domain).config;
  bus::Participant participant(config);
  RunPublisher publisher(participant, args.controller);

  std::string tool_table;
  bool tool_table_inch = false;
  capture::RunTracker tracker([&](const std::string& program) {
    capture::RunProgram p;
    p.text = read_file(program);
    p.tool_table = tool_table;
    p.tool_table_inch = tool_table_inch;
    const setup::ToolList tools = tool_table.empty()
        ? setup::ToolList{}
        : setup::parse_linuxcnc_tool_table(tool_table, tool_table_inch ? setup::LengthUnits::Inches
                                                                       : setup::LengthUnits::Millimeters,
                                           "<LinuxCNC tool table>");
    p.order = capture::execution_order(program, p.text, tools);
    return p;
  });

  int ended = 0;
  std::string last_lost;
  while (!g_stop && (args.runs == 0 || ended < args.runs)) {
    std::unique_ptr<StatusReaderProcess> reader;
    try {
      reader = std::make_unique<StatusReaderProcess>(args.python, args.poll_ms);
      while (!g_stop && (args.runs == 0 || ended < args.runs)) {
        const std::optional<std::string> line = reader->next_line(std::chrono::milliseconds(200));
        if (!line) continue;
        const capture::LinuxcncRecord r = capture::parse_linuxcnc_status_line(*line);
        switch (r.kind) {
          case capture::LinuxcncRecord::Kind::Sample:
            if (!last_lost.empty()) std::fprintf(stderr, "ncbridge capture: connected to LinuxCNC\n");
            last_lost.clear();
            ended += publisher.publish(tracker.observe(r.sample));
            break;
          case capture::LinuxcncRecord::Kind::Tools:
            tool_table = r.tool_table;
            tool_table_inch = r.inch;
            break;
          case capture::LinuxcncRecord::Kind::Lost:
            ended += publisher.publish(tracker.lost(r.reason));
            if (r.reason != last_lost) std::fprintf(stderr, "ncbridge capture: %s; waiting for it\n", r.reason.c_str());
            last_lost = r.reason;
            break;
          case capture::LinuxcncRecord::Kind::Fatal:
            throw InputError({"linuxcnc", 0, 0}, r.reason);
        }
      }
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {  // the reader died: a run in progress is lost; start it again
      ended += publisher.publish(tracker.lost(e.what()));
      std::fprintf(stderr, "ncbridge capture: %s; restarting the status reader\n", e.what());
      std::this_thread::sleep_for(std::chrono::seconds(1));
    }
  }
  ended += publisher.publish(tracker.lost("capture stopped"));
  publisher.drain(std::chrono::seconds(10));
  return 0;
}

// ---- MTConnect

std::size_t append_body(char* data, std::size_t size, std::size_t count, void* out) {
  static_cast<std::string*>(out)->append(data, size * count);
  return size * count;
}

// One GET; throws std::runtime_error on a transport error or an HTTP status other than 200
// (an agent's MTConnectError documents come with 4xx: their text is in the message).
std::string http_get(const std::string& url) {
  std::unique_ptr<CURL, decltype(&curl_easy_cleanup)> curl(curl_easy_init(), curl_easy_cleanup);
  if (!curl) throw std::runtime_error("cannot start an HTTP client");
  std::string body;
  curl_easy_setopt(curl.get(), CURLOPT_URL, url.c_str());
  curl_easy_setopt(curl.get(), CURLOPT_WRITEFUNCTION, append_body);
  curl_easy_setopt(curl.get(), CURLOPT_WRITEDATA, &body);
  curl_easy_setopt(curl.get(), CURLOPT_CONNECTTIMEOUT_MS, 5000L);
  curl_easy_setopt(curl.get(), CURLOPT_TIMEOUT_MS, 15000L);
  curl_easy_setopt(curl.get(), CURLOPT_NOSIGNAL, 1L);
  const CURLcode rc = curl_easy_perform(curl.get());
  if (rc != CURLE_OK) throw std::runtime_error(url + ": " + curl_easy_strerror(rc));
  long status = 0;
  curl_easy_getinfo(curl.get(), CURLINFO_RESPONSE_CODE, &status);
  if (status != 200) {
    try {
      capture::parse_mtconnect_streams(body);
    } catch (const InputError& e) {
      throw std::runtime_error(url + ": HTTP " + std::to_string(status) + ": " + e.message());
    }
    throw std::runtime_error(url + ": HTTP " + std::to_string(status));
  }
  return body;
}

std::string device_path(const std::string& device) { return "path=//Device[@name=%22" + device + "%22]"; }

int run_capture_mtconnect(const CaptureArguments& args) {
  interpreter::Dialect dialect = interpreter::Dialect::Rs274Ngc;
  interpreter::parse_dialect_name(args.dialect, dialect);
  const bus::BusConfig config = client_bus(args.domain).config;
  bus::Participant participant(config);
  const std::string controller = args.controller.empty() ? args.device : args.controller;
  RunPublisher publisher(participant, controller);
  capture::MtconnectDevice device(args.device);
  capture::SampleCursor cursor;
  capture::RunTracker tracker([&](const std::string& program) {
    capture::RunProgram p;
    if (args.program_dir.empty()) return p;  // blocks as the agent reports them
    const std::filesystem::path file = std::filesystem::path(args.program_dir) / std::filesystem::path(program).filename();
    p.text = read_file(file);
    p.order = capture::execution_order(file.string(), p.text, {}, dialect);
    return p;
  });
  std::string agent = args.agent;
  while (!agent.empty() && agent.back() == '/') agent.pop_back();

  int ended = 0;
  std::string last_error;
  // Where to ask: /current at the start and after the agent's buffer moved past us (its latest
  // value of every item: the state now), else /sample from the next sequence.
  while (!g_stop && (args.runs == 0 || ended < args.runs)) {
    const auto started = Clock::now();
    try {
      const std::string count = "count=" + std::to_string(args.count) + "&" + device_path(args.device);
      const std::string url = !cursor.next() ? agent + "/current?" + device_path(args.device)
                                             : agent + "/sample?from=" + std::to_string(*cursor.next()) + "&" + count;
      const capture::MtconnectStreams answer = capture::parse_mtconnect_streams(http_get(url));
      const capture::SampleCursor::Accepted accepted = cursor.accept(answer);
      if (accepted.lost) {
        std::fprintf(stderr, "ncbridge capture: %s\n", accepted.why.c_str());
        ended += publisher.publish(tracker.gap(accepted.why));
      }
      for (const capture::ControllerSample& s : device.observe(accepted.fresh)) ended += publisher.publish(tracker.observe(s));
      if (!last_error.empty()) std::fprintf(stderr, "ncbridge capture: connected to the agent again\n");
      last_error.clear();
      // A full answer means more is waiting: ask again at once.
      if (static_cast<int>(answer.observations.size()) >= args.count) continue;
    } catch (const std::exception& e) {
      const std::string what = e.what();
      if (what.find("OUT_OF_RANGE") != std::string::npos && cursor.next()) {  // the buffer moved past us
        const std::string why = "the agent's buffer no longer holds sequence " + std::to_string(*cursor.next());
        std::fprintf(stderr, "ncbridge capture: %s; reading its current state\n", why.c_str());
        ended += publisher.publish(tracker.gap(why));
        cursor.resync();
        continue;
      }
      if (what != last_error) std::fprintf(stderr, "ncbridge capture: %s; retrying\n", what.c_str());
      last_error = what;
    }
    std::this_thread::sleep_until(started + std::chrono::microseconds(static_cast<long long>(args.interval_ms * 1000)));
  }
  ended += publisher.publish(tracker.lost("capture stopped"));
  publisher.drain(std::chrono::seconds(10));
  return 0;
}

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

}  // namespace

void add_capture_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CaptureArguments>();
  CLI::App* cmd = app.add_subcommand("capture", "Publish what a real controller executes (live capture)");
  cmd->require_subcommand(1);
  auto common = [&](CLI::App* sub) {
    sub->add_option("--domain", args->domain, "DDS domain id (default: NCBRIDGE_DDS_DOMAIN, else the running ncbridge up's)")->check(CLI::Range(0, 230));
    sub->add_option("--runs", args->runs, "Stop after this many runs ended (default: run until stopped)")
        ->check(CLI::NonNegativeNumber);
  };
  CLI::App* lcnc = cmd->add_subcommand("linuxcnc", "Beside a LinuxCNC controller, as its user: every program run becomes a job");
  lcnc->add_option("--controller", args->controller, "Controller id (the runs' jobs are ID/run-...)")->required();
  lcnc->add_option("--poll-ms", args->poll_ms, "Status period in ms (default 5)")->check(CLI::Range(1.0, 1000.0));
  lcnc->add_option("--python", args->python, "The Python that has LinuxCNC's module (default /usr/bin/python3)");
  common(lcnc);
  lcnc->callback([args, &exit_code]() {
    install_stop_handlers();
    exit_code = run_capture_linuxcnc(*args);
  });
  CLI::App* mtc = cmd->add_subcommand("mtconnect", "From an MTConnect agent's sample stream");
  mtc->add_option("agent", args->agent, "The agent's address, e.g. http://agent:5000")->required();
  mtc->add_option("--device", args->device, "The device's name at the agent")->required();
  mtc->add_option("--controller", args->controller, "Controller id (default: the device name)");
  mtc->add_option("--program-dir", args->program_dir,
                  "Folder with the programs the device runs (by the Program item's file name): their lines are "
                  "followed; without it, the agent's Block texts are published");
  mtc->add_option("--dialect", args->dialect, "Dialect of the programs in --program-dir")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain"}));
  mtc->add_option("--interval-ms", args->interval_ms, "Polling period in ms (default 200)")->check(CLI::Range(10.0, 60000.0));
  mtc->add_option("--count", args->count, "Observations asked for per /sample (default 1000)")->check(CLI::Range(1, 100000));
  common(mtc);
  mtc->callback([args, &exit_code]() {
    install_stop_handlers();
    curl_global_init(CURL_GLOBAL_DEFAULT);
    exit_code = run_capture_mtconnect(*args);
    curl_global_cleanup();
  });
}

}  // namespace ncbridge::cli
