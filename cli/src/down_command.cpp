// `ncbridge down [--domain D]`: stops the `ncbridge up` this user runs on this machine (the one
// running, or the one on --domain / NCBRIDGE_DDS_DOMAIN): SIGTERM, which makes it stop its
// services cleanly, then waits until it has exited (it removes its record; a record whose
// process is gone is removed here). Nothing running is not an error: it says so.
#include <CLI/CLI.hpp>
#include <signal.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "commands.hpp"
#include "errors.hpp"
#include "up_registry.hpp"
#include "ncbridge/bus/config.hpp"

namespace ncbridge::cli {
namespace {

struct DownArguments {
  std::optional<std::uint32_t> domain;
  double timeout_s = 30;
};

int run_down(const DownArguments& args) {
  std::optional<std::uint32_t> domain = args.domain;
  if (const char* env = std::getenv("NCBRIDGE_DDS_DOMAIN"); !domain && env != nullptr && *env != '\0')
    domain = bus::config_from_environment().domain_id;
  std::vector<UpRecord> running = live_up_records();
  if (domain) std::erase_if(running, [&](const UpRecord& r) { return r.domain != *domain; });
  if (running.empty()) {
    std::fprintf(stderr, "ncbridge: no ncbridge up runs for this user%s\n",
                 domain ? (" on DDS domain " + std::to_string(*domain)).c_str() : "");
    return exit_status::ok;
  }
  if (running.size() > 1) {
    std::string domains;
    for (const UpRecord& r : running) domains += (domains.empty() ? "" : ", ") + std::to_string(r.domain);
    throw UsageError("several `ncbridge up` run (DDS domains " + domains + "): say which with --domain");
  }
  const UpRecord up = running.front();
  if (kill(up.pid, SIGTERM) != 0 && errno != ESRCH)
    throw ServiceUnavailable("cannot stop ncbridge up (pid " + std::to_string(up.pid) + "): " + std::strerror(errno));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long long>(args.timeout_s * 1000));
  while (is_live(up)) {
    if (std::chrono::steady_clock::now() > deadline)
      throw ServiceUnavailable("ncbridge up (pid " + std::to_string(up.pid) + ") still runs " +
                               std::to_string(static_cast<long long>(args.timeout_s)) + " s after SIGTERM");
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  remove_up_record(up.domain);  // gone already when up stopped itself
  std::fprintf(stderr, "ncbridge: stopped ncbridge up on DDS domain %u (pid %d)\n", up.domain, static_cast<int>(up.pid));
  return exit_status::ok;
}

}  // namespace

void add_down_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<DownArguments>();
  CLI::App* cmd = app.add_subcommand("down", "Stop the ncbridge up running for this user (its services too)");
  cmd->add_option("--domain", args->domain, "Its DDS domain id, when several run (default: NCBRIDGE_DDS_DOMAIN)")
      ->check(CLI::Range(0, 230));
  cmd->add_option("--timeout", args->timeout_s, "Seconds to wait for it to stop (default 30)")->check(CLI::PositiveNumber);
  cmd->callback([args, &exit_code]() { exit_code = run_down(*args); });
}

}  // namespace ncbridge::cli
