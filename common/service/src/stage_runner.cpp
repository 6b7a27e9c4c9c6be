#include "ncbridge/service/stage_runner.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <set>
#include <utility>

#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/worker_directory.hpp"
#include "ncbridge/bus/worker_presence.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/wire/status.hpp"

namespace ncbridge::service {

using Clock = std::chrono::steady_clock;

namespace {

wire::WorkerInfo worker_info(const std::string& stage, const std::string& worker_id) {
  wire::WorkerInfo info = bus::this_process_worker(stage);
  if (!worker_id.empty()) info.worker_id = worker_id;
  return info;
}

}  // namespace

struct StageRunner::State {
  State(bus::Participant& participant, StageSpec s, RunnerOptions o)
      : spec(std::move(s)),
        options(std::move(o)),
        presence(participant, worker_info(spec.stage, options.worker_id)),
        directory(participant),
        status_reader(participant, bus::Topic::Status),
        status_writer(participant, bus::Topic::Status),
        output(participant, spec.output) {
    for (const InputTopic& in : spec.inputs) inputs.emplace_back(in, bus::Reader(participant, in.topic));
  }

  const std::string& me() const { return presence.info().worker_id; }

  void publish_status(wire::JobStatus status) {
    status.stage = spec.stage;
    status.worker_id = me();
    const std::string subkey = status.job_id.empty() ? spec.stage + "/" + me() : spec.stage;
    status_writer.write(status.job_id, subkey, status_seq++, static_cast<std::uint32_t>(status.state), false,
                        wire::encode_status(status));
  }

  void health(const std::string& message) {
    wire::JobStatus s;
    s.state = wire::JobState::Running;
    s.message = message;
    publish_status(std::move(s));
  }

  void take_inputs(std::chrono::milliseconds first_wait) {
    bool first = true;
    for (auto& [in, reader] : inputs) {
      for (const bus::Received& r : reader.take(first ? first_wait : std::chrono::milliseconds(0))) {
        if (!r.has_data) continue;
        const std::string job_id =
            in.job_id_includes_subkey ? r.envelope.key + "/" + r.envelope.subkey : r.envelope.key;
        if (assembler.add(in.topic, job_id, r.envelope)) spdlog::debug("job {}: input complete", job_id);
      }
      first = false;
    }
  }

  void take_statuses() {
    for (const bus::Received& r : status_reader.take(std::chrono::milliseconds(0))) {
      if (!r.has_data || r.envelope.key.empty()) continue;
      wire::JobStatus s;
      try {
        s = wire::decode_status(r.envelope.payload);
      } catch (const InputError& e) {
        spdlog::warn("ignoring a malformed status sample of job {}: {}", r.envelope.key, e.what());
        continue;
      }
      const bool over = s.state == wire::JobState::Error ||
                        (s.state == wire::JobState::Done && s.stage == bus::kStageStepWriter);
      if (over) job_over(r.envelope.key);
    }
  }

  void job_over(const std::string& job_id) {
    if (assembler.finished(job_id)) return;
    assembler.finish(job_id);
    if (published.erase(job_id) != 0 && spec.unregister_output_when_over) {
      try {
        output.unregister(job_id, "");
      } catch (const std::exception& e) {
        spdlog::warn("job {}: cannot unregister its output: {}", job_id, e.what());
      }
    }
  }

  void run_owned_jobs() {
    for (const std::string& job_id : assembler.complete_jobs()) {
      if (ran.contains(job_id) || !directory.tracker().owns(spec.stage, me(), job_id)) continue;
      if (const JobInput* input = assembler.complete(job_id)) run_job(*input);
    }
  }

  void run_job(const JobInput& input) {
    const std::string job_id = input.job_id;  // input is dropped if the job ends in here
    const auto start = Clock::now();
    ran.insert(job_id);
    published.insert(job_id);
    presence.update_jobs({job_id});
    wire::JobStatus running;
    running.job_id = job_id;
    running.state = wire::JobState::Running;
    publish_status(running);
    Clock::time_point last_progress = start;
    JobContext context(&output, [&](double fraction) {
      const auto now = Clock::now();
      if (now - last_progress < std::chrono::milliseconds(200)) return;
      last_progress = now;
      wire::JobStatus p;
      p.job_id = job_id;
      p.state = wire::JobState::Progress;
      p.progress = fraction;
      publish_status(std::move(p));
    }, me());
    wire::JobStatus end;
    try {
      spec.run(input, context);
      end.job_id = job_id;
      end.state = wire::JobState::Done;
      end.progress = 1;
      spdlog::info("job {}: done in {:.1f} ms", job_id,
                   std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    } catch (const InputError& e) {
      end = wire::error_status(job_id, spec.stage, me(), e);
      spdlog::warn("job {}: {}", job_id, e.what());
    } catch (const std::exception& e) {
      end.job_id = job_id;
      end.state = wire::JobState::Error;
      end.message = e.what();
      spdlog::error("job {}: {}", job_id, e.what());
    }
    publish_status(end);
    presence.update_jobs({});
    if (end.state == wire::JobState::Error) job_over(job_id);
  }

  StageSpec spec;
  RunnerOptions options;
  bus::WorkerPresence presence;
  bus::WorkerDirectory directory;
  bus::Reader status_reader;
  bus::Writer status_writer;
  bus::Writer output;
  std::vector<std::pair<InputTopic, bus::Reader>> inputs;
  JobAssembler assembler;
  std::set<std::string, std::less<>> ran;        // jobs this worker ran (never twice)
  std::set<std::string, std::less<>> published;  // jobs with an output instance to unregister
  std::uint64_t status_seq = 0;
};

StageRunner::StageRunner(bus::Participant& participant, StageSpec spec, RunnerOptions options)
    : state_(std::make_unique<State>(participant, std::move(spec), std::move(options))) {}

StageRunner::~StageRunner() = default;

const std::string& StageRunner::worker_id() const { return state_->me(); }

int StageRunner::run(ShutdownSignal& shutdown) {
  State& s = *state_;
  spdlog::info("{} worker {} up", s.spec.stage, s.me());
  s.health("ready");
  const auto started = Clock::now();
  bool settled = false;
  while (!shutdown.requested()) {
    s.take_inputs(s.options.poll);
    s.take_statuses();
    s.directory.poll(std::chrono::milliseconds(0));
    if (!settled) {
      // Until this worker sees itself (and had time to hear of its peers), it owns nothing.
      const auto live = s.directory.tracker().live_workers(s.spec.stage);
      settled = Clock::now() - started >= s.options.settle &&
                std::find(live.begin(), live.end(), s.me()) != live.end();
      if (!settled) continue;
      spdlog::info("{} worker {}: {} live worker(s) of the stage", s.spec.stage, s.me(), live.size());
    }
    s.run_owned_jobs();
  }
  spdlog::info("{} worker {}: stopping", s.spec.stage, s.me());
  wire::JobStatus stopped;
  stopped.state = wire::JobState::Done;
  stopped.message = "stopped";
  s.publish_status(std::move(stopped));
  s.status_writer.wait_for_acks(std::chrono::milliseconds(500));
  return 0;
}

}  // namespace ncbridge::service
