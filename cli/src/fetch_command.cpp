// `ncbridge fetch JOB... [-o FILE | --output-dir DIR]`: the Part 21 files of jobs submitted
// earlier (`submit` without --wait, `submit --detach`, a controller's run), from the result topic:
// the step writer keeps each job's file there until a client has it whole (then says
// Delivered and the step writer lets go of it) or the retention policy (up --retain-*) drops it.
// A job not over yet is waited for (--timeout). Each file appears whole or not at all
// (output_files.hpp); with --output-dir it is named as the step writer names it (the program's
// stem, .stp). A job the services do not know, one that failed or was cancelled, and one whose
// file has left the bus already (fetched before) are errors (exit 1), said one line each.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "client_bus.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "output_files.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/topics.hpp"
#include "ncbridge/service/job_watch.hpp"
#include "ncbridge/wire/status.hpp"

namespace ncbridge::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct FetchArguments {
  std::vector<std::string> jobs;
  std::string output;
  std::string output_dir;
  std::optional<std::uint32_t> domain;
  double timeout_s = 600;
  double listen_s = 3;  // how long a job may stay unheard of, or its file absent once done
};

struct Fetched {
  OutputSet set;
  OutputFile* file = nullptr;
};

int run_fetch(const FetchArguments& args) {
  if (args.jobs.size() > 1 && !args.output.empty()) throw UsageError("-o: only with one job (several: --output-dir)");
  if (!args.output.empty() && !args.output_dir.empty()) throw UsageError("-o and --output-dir: give one");
  std::set<std::string> unique(args.jobs.begin(), args.jobs.end());
  if (unique.size() != args.jobs.size()) throw UsageError("a job is named twice");
  const fs::path dir = args.output.empty() ? prepare_output_directory(args.output_dir.empty() ? "." : args.output_dir, "--output-dir")
                                           : fs::path();
  std::map<std::string, Fetched> out;
  if (!args.output.empty()) {
    Fetched& f = out[args.jobs.front()];
    f.file = &f.set.add(args.output, "-o");
  }

  const ClientBus bus = client_bus(args.domain);
  bus::Participant participant(bus.config);
  service::JobWatch watch(participant, args.jobs);
  const auto start = Clock::now();
  const auto deadline = start + std::chrono::milliseconds(static_cast<long long>(args.timeout_s * 1000));
  const auto listen = std::chrono::milliseconds(static_cast<long long>(args.listen_s * 1000));
  std::set<std::string> pending(args.jobs.begin(), args.jobs.end());
  std::set<std::string> heard_of;                     // a status of it came
  std::map<std::string, Clock::time_point> written;   // the step writer said done, at
  std::set<std::string> receiving;                    // a piece of its file came
  int failed = 0, not_written = 0;
  std::size_t fetched = 0;

  const auto on_piece = [&](const std::string& job_id, const wire::Part21File& piece) {
    receiving.insert(job_id);
    Fetched& f = out[job_id];
    if (f.file == nullptr) {
      const std::string name = fs::path(piece.file_name).filename().string();
      f.file = &f.set.add((dir / (name.empty() || name == "." || name == ".." ? job_id + ".stp" : name)).string(), "--output-dir");
    }
    f.file->write(piece.content);
  };
  const auto on_over = [&](const std::string& job_id, service::JobOutcome outcome) {
    pending.erase(job_id);
    if (outcome.error) {
      const wire::JobStatus& e = *outcome.error;
      if (e.state == wire::JobState::Cancelled) print_error("job " + job_id + " was cancelled");
      else print_error(e.where, e.message + " (" + e.stage + ")");
      ++failed;
      out.erase(job_id);
      return;
    }
    Fetched& f = out.at(job_id);
    try {
      f.set.commit();
      std::fprintf(stderr, "%s: %s\n", job_id.c_str(), f.file->display_name().c_str());
      ++fetched;
    } catch (const OutputError& e) {
      print_error({e.path().string(), 0, 0}, e.message());
      ++not_written;
    }
    out.erase(job_id);
  };
  const auto on_status = [&](const wire::JobStatus& s) {
    heard_of.insert(s.job_id);
    if (s.stage == bus::kStageStepWriter && s.state == wire::JobState::Done) written.emplace(s.job_id, Clock::now());
  };
  while (!pending.empty() && Clock::now() < deadline) {
    watch.wait_all(std::chrono::milliseconds(100), on_piece, on_over, on_status);
    const auto now = Clock::now();
    for (auto it = pending.begin(); it != pending.end();) {
      const std::string& job = *it;
      std::string why;
      if (!heard_of.contains(job) && now - start > listen) {
        why = "job " + job + ": the services on DDS domain " + std::to_string(bus.config.domain_id) +
              " know no such job (never submitted, or over longer ago than their --retain-for)";
      } else if (const auto w = written.find(job); w != written.end() && now - w->second > listen && !receiving.contains(job)) {
        why = "job " + job + ": done, but its file is no longer on the bus (fetched already, or dropped by --retain-*)";
        if (bus.up && !bus.up->output_dir.empty()) why += "; the step writers wrote it into " + bus.up->output_dir;
      }
      if (why.empty()) {
        ++it;
        continue;
      }
      print_error(why);
      ++failed;
      it = pending.erase(it);
    }
  }
  for (const std::string& job : pending)
    print_error("job " + job + " not over after " + std::to_string(static_cast<long long>(args.timeout_s)) + " s (--timeout)");
  if (!pending.empty()) return exit_status::service_unavailable;
  if (not_written > 0) return exit_status::output_error;
  return failed > 0 ? exit_status::input_error : exit_status::ok;
}

}  // namespace

void add_fetch_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<FetchArguments>();
  CLI::App* cmd = app.add_subcommand("fetch", "Get the Part 21 files of jobs submitted earlier (waits for those not done)");
  cmd->add_option("jobs", args->jobs, "Job ids, as submit printed them")->required();
  cmd->add_option("-o,--output", args->output, "Part 21 file to write (one job; - for standard output)");
  cmd->add_option("--output-dir", args->output_dir,
                  "Directory for the files, named as the step writer names them (default: the current one)");
  cmd->add_option("--domain", args->domain, "DDS domain id (default: NCBRIDGE_DDS_DOMAIN, else the running ncbridge up's)")
      ->check(CLI::Range(0, 230));
  cmd->add_option("--timeout", args->timeout_s, "Seconds to wait for jobs not done (default 600)");
  cmd->callback([args, &exit_code]() { exit_code = run_fetch(*args); });
}

}  // namespace ncbridge::cli
