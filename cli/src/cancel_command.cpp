// `ncbridge cancel JOB...`: asks the services to drop jobs queued or running. It says so on the
// status topic (Cancelled, stage "client"); every worker drops the job, and the one that had it
// says Cancelled in its stage, which `status`, `fetch` and a waiting `submit` then show. A job
// over already (done, failed, cancelled) is left as it is and said so; a job no worker confirms
// and no status names is unknown to the services: an error (exit 1). docs/cli.md.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "client_bus.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/routing.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/topics.hpp"
#include "ncbridge/bus/writer.hpp"
#include "ncbridge/wire/status.hpp"

namespace ncbridge::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct CancelArguments {
  std::vector<std::string> jobs;
  std::optional<std::uint32_t> domain;
  double listen_s = 1.5;
  double timeout_s = 5;
};

// How a job ended, from its statuses so far; empty while it is not over.
std::string ending(const std::map<std::string, wire::JobStatus>& stages) {
  for (const auto& [stage, s] : stages) {
    if (s.state == wire::JobState::Cancelled) return "cancelled already";
    if (s.state == wire::JobState::Error) return "failed already (" + stage + ": " + s.message + ")";
    if ((stage == bus::kStageStepWriter && s.state == wire::JobState::Done) || s.state == wire::JobState::Delivered)
      return "done already";
  }
  return {};
}

int run_cancel(const CancelArguments& args) {
  const ClientBus bus = client_bus(args.domain);
  bus::Participant participant(bus.config);
  bus::Reader statuses(participant, bus::Topic::Status);
  bus::Writer requests(participant, bus::Topic::Status);
  // Workers read only the statuses that end a job, in their own partition (bus/routing.hpp).
  bus::Writer requests_to_workers(participant, bus::Topic::Status, bus::kJobOverPartition);
  std::map<std::string, std::map<std::string, wire::JobStatus>> known;  // job -> stage -> latest
  const std::set<std::string> wanted(args.jobs.begin(), args.jobs.end());
  const auto take = [&](std::chrono::milliseconds wait) {
    for (const bus::Received& r : statuses.take(wait, 4096)) {
      if (!r.has_data || !wanted.contains(r.envelope.key)) continue;
      try {
        wire::JobStatus s = wire::decode_status(r.envelope.payload);
        known[r.envelope.key][s.stage] = std::move(s);
      } catch (const InputError&) {
      }
    }
  };
  // What the status topic holds of the jobs (it is durable: a moment's listening is enough).
  for (const auto until = Clock::now() + std::chrono::milliseconds(static_cast<long long>(args.listen_s * 1000));
       Clock::now() < until;)
    take(std::chrono::milliseconds(50));

  // Known to the services: a status of it before we asked, or a worker's after.
  std::set<std::string> known_before;
  for (const auto& [job, stages] : known) known_before.insert(job);
  int failed = 0;
  std::set<std::string> asked;
  for (const std::string& job : args.jobs) {
    // A job with no status yet may still be arriving (a controller's run): asked too.
    const auto it = known.find(job);
    if (it != known.end()) {
      if (const std::string over = ending(it->second); !over.empty()) {
        std::printf("%s: %s\n", job.c_str(), over.c_str());
        continue;
      }
    }
    wire::JobStatus request;
    request.job_id = job;
    request.stage = bus::kStageClient;
    request.state = wire::JobState::Cancelled;
    request.message = "cancelled (ncbridge cancel)";
    const std::string bytes = wire::encode_status(request);
    requests.write(job, bus::kStageClient, 0, static_cast<std::uint32_t>(request.state), true, bytes);
    requests_to_workers.write(job, bus::kStageClient, 0, static_cast<std::uint32_t>(request.state), true, bytes);
    asked.insert(job);
  }
  // Until a worker says Cancelled (or the job ended otherwise meanwhile); the request stays on the
  // bus as long as this process does.
  const auto deadline = Clock::now() + std::chrono::milliseconds(static_cast<long long>(args.timeout_s * 1000));
  while (!asked.empty() && Clock::now() < deadline) {
    take(std::chrono::milliseconds(50));
    for (auto it = asked.begin(); it != asked.end();) {
      const auto& stages = known[*it];
      std::string said;
      for (const auto& [stage, s] : stages) {
        if (stage == bus::kStageClient) continue;
        if (s.state == wire::JobState::Cancelled) said = "cancelled (" + stage + " " + s.worker_id + ")";
        else if (said.empty() && s.state == wire::JobState::Error) said = "failed before it was cancelled (" + s.message + ")";
        else if (said.empty() && stage == bus::kStageStepWriter && s.state == wire::JobState::Done) said = "done before it was cancelled";
      }
      if (said.empty()) {
        ++it;
        continue;
      }
      std::printf("%s: %s\n", it->c_str(), said.c_str());
      it = asked.erase(it);
    }
  }
  requests.wait_for_acks(std::chrono::milliseconds(2000));
  requests_to_workers.wait_for_acks(std::chrono::milliseconds(2000));
  // No worker answered: the job was asked to stop everywhere, but none had it in hand (between
  // two stages), or the services never heard of it.
  for (const std::string& job : asked) {
    const auto& stages = known[job];
    if (known_before.contains(job) || std::any_of(stages.begin(), stages.end(), [](const auto& s) { return s.first != bus::kStageClient; })) {
      std::printf("%s: cancelled (no worker had it in hand)\n", job.c_str());
    } else {
      print_error("job " + job + ": the services on DDS domain " + std::to_string(bus.config.domain_id) + " know no such job");
      ++failed;
    }
  }
  std::fflush(stdout);
  return failed > 0 ? exit_status::input_error : exit_status::ok;
}

}  // namespace

void add_cancel_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CancelArguments>();
  CLI::App* cmd = app.add_subcommand("cancel", "Cancel jobs queued or running in the DDS services");
  cmd->add_option("jobs", args->jobs, "Job ids, as submit printed them")->required();
  cmd->add_option("--domain", args->domain, "DDS domain id (default: NCBRIDGE_DDS_DOMAIN, else the running ncbridge up's)")
      ->check(CLI::Range(0, 230));
  cmd->add_option("--timeout", args->timeout_s, "Seconds to wait for a worker to confirm (default 5)");
  cmd->callback([args, &exit_code]() { exit_code = run_cancel(*args); });
}

}  // namespace ncbridge::cli
