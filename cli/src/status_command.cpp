// `ncbridge status`: the live workers of each stage (workers topic) and every job the status
// topic still holds, with each stage's latest state. Both topics are durable, so listening for
// a moment (--listen) gives the current picture. A job not over that no live worker has (the
// worker that reported it last is gone, or a stage it still needs has no live worker) is marked
// "stalled", not shown as running forever.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "client_bus.hpp"
#include "commands.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/topics.hpp"
#include "ncbridge/bus/worker_tracker.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/wire/status.hpp"
#include "ncbridge/wire/worker.hpp"

namespace ncbridge::cli {
namespace {

struct StatusArguments {
  std::optional<std::uint32_t> domain;
  double listen_s = 1.5;
  std::string controller;  // only this controller's captured runs
};

const char* state_name(wire::JobState s) {
  switch (s) {
    case wire::JobState::Queued: return "queued";
    case wire::JobState::Running: return "running";
    case wire::JobState::Progress: return "progress";
    case wire::JobState::Done: return "done";
    case wire::JobState::Error: return "ERROR";
    case wire::JobState::Delivered: return "delivered";
    case wire::JobState::Cancelled: return "cancelled";
  }
  return "?";
}

using Stages = std::map<std::string, wire::JobStatus>;  // stage -> latest status of a job

constexpr std::array<std::string_view, 4> kPipeline{bus::kStageInterpreter, bus::kStageCc1Builder,
                                                    bus::kStageFeatureRecognizer, bus::kStageStepWriter};

bool is_over(const Stages& stages) {
  for (const auto& [stage, s] : stages) {
    if (s.state == wire::JobState::Error || s.state == wire::JobState::Cancelled || s.state == wire::JobState::Delivered) return true;
    if (stage == bus::kStageStepWriter && s.state == wire::JobState::Done) return true;
  }
  return false;
}

// Why a job not over is stuck, or nothing when a live worker has it or can take it on: the
// worker that reported its latest work is gone, or a stage after its last finished one has no
// live worker (the reverse: its work cannot go on).
std::optional<std::string> stalled(const std::string& job, const Stages& stages, const bus::WorkerTracker& tracker,
                                   const std::map<std::string, wire::WorkerInfo>& infos) {
  if (is_over(stages)) return std::nullopt;
  for (const auto& [worker, info] : infos) {
    const auto live = tracker.live_workers(info.stage);
    if (std::find(live.begin(), live.end(), worker) == live.end()) continue;
    if (std::find(info.jobs_in_progress.begin(), info.jobs_in_progress.end(), job) != info.jobs_in_progress.end())
      return std::nullopt;  // a live worker says it works on it
  }
  std::size_t last = 0;  // the pipeline position after the last stage that reported
  for (std::size_t i = 0; i < kPipeline.size(); ++i) {
    const auto it = stages.find(std::string(kPipeline[i]));
    if (it == stages.end()) continue;
    last = i + 1;
    const wire::JobStatus& s = it->second;
    if (s.state == wire::JobState::Done) continue;
    const auto live = tracker.live_workers(kPipeline[i]);
    if (!s.worker_id.empty() && std::find(live.begin(), live.end(), s.worker_id) == live.end() && live.empty())
      return std::string(kPipeline[i]) + " worker " + s.worker_id + " is gone and no other is live";
  }
  for (std::size_t i = last; i < kPipeline.size(); ++i) {
    if (kPipeline[i] == bus::kStageFeatureRecognizer) continue;  // CC1 jobs pass it by
    if (tracker.live_workers(kPipeline[i]).empty()) return "no live " + std::string(kPipeline[i]) + " worker";
  }
  return std::nullopt;
}

// A controller's captured runs (jobs "CONTROLLER/RUN"): converted (and the file's name), in
// progress, aborted by the controller, or failed.
int print_runs(const std::string& controller, const std::map<std::string, Stages>& jobs, const bus::WorkerTracker& tracker,
               const std::map<std::string, wire::WorkerInfo>& infos) {
  const std::string prefix = controller + "/";
  std::size_t n = 0;
  for (const auto& [job, stages] : jobs) n += job.starts_with(prefix) ? 1 : 0;
  std::printf("runs captured from %s: %zu\n", controller.c_str(), n);
  for (const auto& [job, stages] : jobs) {
    if (!job.starts_with(prefix)) continue;
    std::string outcome = "in progress";
    for (const auto& [stage, status] : stages) {
      if (status.state == wire::JobState::Error) {
        outcome = (status.message.find("run aborted") != std::string::npos ? "aborted: " : "ERROR: ") +
                  status.where.to_string() + ": " + status.message;
      }
      if (status.state == wire::JobState::Cancelled) outcome = "cancelled";
    }
    const auto writer = stages.find(std::string(bus::kStageStepWriter));
    if (outcome == "in progress" && writer != stages.end() &&
        (writer->second.state == wire::JobState::Done || writer->second.state == wire::JobState::Delivered)) {
      std::string file = job;
      for (char& c : file) c = c == '/' ? '-' : c;
      outcome = "converted: " + file + ".stp";
    }
    if (outcome == "in progress") {
      if (const auto why = stalled(job, stages, tracker, infos)) outcome = "stalled: " + *why;
    }
    std::printf("  %s  %s\n", job.c_str(), outcome.c_str());
  }
  return 0;
}

int run_status(const StatusArguments& args) {
  bus::Participant participant(client_bus(args.domain).config);
  bus::Reader workers(participant, bus::Topic::Workers);
  bus::Reader statuses(participant, bus::Topic::Status);
  bus::WorkerTracker tracker;
  std::map<std::string, wire::WorkerInfo> infos;  // worker id -> latest announcement
  std::map<std::string, Stages> jobs;  // job -> stage -> status
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long long>(args.listen_s * 1000));
  while (std::chrono::steady_clock::now() < deadline) {
    for (const bus::Received& r : workers.take(std::chrono::milliseconds(20))) {
      tracker.apply(r);
      if (r.has_data) {
        try {
          infos[r.envelope.subkey] = wire::decode_worker(r.envelope.payload);
        } catch (const InputError&) {
        }
      }
    }
    for (const bus::Received& r : statuses.take(std::chrono::milliseconds(0))) {
      if (!r.has_data || r.envelope.key.empty()) continue;
      try {
        wire::JobStatus s = wire::decode_status(r.envelope.payload);
        jobs[r.envelope.key][s.stage] = std::move(s);
      } catch (const InputError&) {
      }
    }
  }
  if (!args.controller.empty()) return print_runs(args.controller, jobs, tracker, infos);
  std::printf("workers (DDS domain %u):\n", participant.domain_id());
  for (std::string_view stage : {bus::kStageInterpreter, bus::kStageCc1Builder, bus::kStageFeatureRecognizer,
                                 bus::kStageStepWriter}) {
    const auto live = tracker.live_workers(stage);
    std::printf("  %-19s %zu live", std::string(stage).c_str(), live.size());
    for (const std::string& w : live) {
      const auto it = infos.find(w);
      const bool busy = it != infos.end() && !it->second.jobs_in_progress.empty();
      std::printf("  %s%s", w.c_str(), busy ? (" (busy: " + it->second.jobs_in_progress.front() + ")").c_str() : "");
    }
    std::printf("\n");
  }
  std::printf("jobs: %zu\n", jobs.size());
  for (const auto& [job, stages] : jobs) {
    std::printf("  %s", job.c_str());
    for (std::string_view stage : {bus::kStageInterpreter, bus::kStageCc1Builder, bus::kStageFeatureRecognizer,
                                   bus::kStageStepWriter}) {
      const auto it = stages.find(std::string(stage));
      if (it == stages.end()) continue;
      std::printf("  %s:%s", std::string(stage).c_str(), state_name(it->second.state));
      if (it->second.state == wire::JobState::Error)
        std::printf(" [%s: %s]", it->second.where.to_string().c_str(), it->second.message.c_str());
    }
    if (const auto client = stages.find(std::string(bus::kStageClient)); client != stages.end()) {
      if (client->second.state == wire::JobState::Cancelled) std::printf("  cancelled");
      if (client->second.state == wire::JobState::Delivered) std::printf("  delivered");
    }
    if (const auto why = stalled(job, stages, tracker, infos)) std::printf("  [stalled: %s]", why->c_str());
    std::printf("\n");
  }
  return 0;
}

}  // namespace

void add_status_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<StatusArguments>();
  CLI::App* cmd = app.add_subcommand("status", "List the DDS services' workers and jobs");
  cmd->add_option("--domain", args->domain, "DDS domain id (default: NCBRIDGE_DDS_DOMAIN, else the running ncbridge up's)")->check(CLI::Range(0, 230));
  cmd->add_option("--listen", args->listen_s, "Seconds to listen before printing (default 1.5)");
  cmd->add_option("--controller", args->controller, "Only the runs captured from this controller, and their files");
  cmd->callback([args, &exit_code]() { exit_code = run_status(*args); });
}

}  // namespace ncbridge::cli
