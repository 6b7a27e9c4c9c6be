#include "ncbridge/service/stage_runner.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <deque>
#include <map>
#include <stdexcept>
#include <utility>

#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/routed_writer.hpp"
#include "ncbridge/bus/routing.hpp"
#include "ncbridge/bus/wait_set.hpp"
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

// A job input goes to its owner in the next stage; anything else to every reader.
std::unique_ptr<bus::SampleWriter> output_writer(bus::Participant& participant, bus::Topic topic) {
  if (!bus::routed_to(topic)) return std::make_unique<bus::Writer>(participant, topic);
  auto routed = std::make_unique<bus::RoutedWriter>(participant, topic);
  routed->report_to([](const std::string& message) { spdlog::info("{}", message); });
  return routed;
}

// A job input is read from this worker's partition (only its jobs); anything else from all.
std::string input_partition(bus::Topic topic, const std::string& stage, const std::string& worker_id) {
  return bus::routed_to(topic) ? bus::worker_partition(stage, worker_id) : std::string();
}

// A whole-input stage as a stream: collects the samples, runs the stage after the last.
class CollectingStream final : public JobStream {
 public:
  CollectingStream(const JobKey& key, JobContext& context, const std::function<void(const JobInput&, JobContext&)>& run)
      : context_(context), run_(run) {
    input_.topic = key.topic;
    input_.job_id = key.job_id;
    input_.subkey = key.subkey;
  }
  void sample(bus::Envelope sample) override {
    input_.payloads.push_back(std::move(sample.payload));
    input_.kinds.push_back(sample.kind);
  }
  void finish() override { run_(input_, context_); }

 private:
  JobInput input_;
  JobContext& context_;
  const std::function<void(const JobInput&, JobContext&)>& run_;
};

}  // namespace

void JobContext::check_time() const {
  if (time_limit_.count() <= 0 || Clock::now() - started_ <= time_limit_) return;
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", static_cast<double>(time_limit_.count()) / 1000.0);
  throw JobTimeLimit("job " + job_id_ + " ran longer than the job time limit (" + seconds +
                     " s, --max-job-seconds) and was stopped");
}

void JobContext::publish_on(bus::Topic topic, std::string_view subkey, std::uint64_t seq, std::uint32_t kind, bool last,
                            std::string_view payload) {
  check_time();
  const auto it = std::find_if(outputs_.begin(), outputs_.end(), [topic](const bus::SampleWriter* w) { return w->topic() == topic; });
  if (it == outputs_.end()) throw std::logic_error("the stage does not publish on " + std::string(bus::topic_name(topic)));
  (*it)->write(job_id_, subkey, seq, kind, last, payload);
  published_.emplace(topic, subkey);
  bytes_ += payload.size();
}

struct StageRunner::State {
  State(bus::Participant& participant, StageSpec s, RunnerOptions o)
      : spec(std::move(s)),
        options(std::move(o)),
        presence(participant, worker_info(spec.stage, options.worker_id)),
        directory(participant),
        status_reader(participant, bus::Topic::Status, bus::kJobOverPartition),
        status_writer(participant, bus::Topic::Status),
        over_writer(participant, bus::Topic::Status, bus::kJobOverPartition),
        output(output_writer(participant, spec.output)),
        wait_set(participant) {
    for (const InputTopic& in : spec.inputs)
      inputs.emplace_back(in, bus::Reader(participant, in.topic, input_partition(in.topic, spec.stage, me())));
    for (const bus::Topic t : spec.other_outputs) other_outputs.push_back(output_writer(participant, t));
    for (const auto& [in, reader] : inputs) wait_set.attach(reader);
    wait_set.attach(status_reader);
    wait_set.attach(directory.reader());
  }

  // A job this worker works on.
  struct Active {
    std::unique_ptr<JobContext> context;
    std::unique_ptr<JobStream> stream;
    Clock::time_point start;
    Clock::time_point last_progress;
  };
  // A job over whose statuses (and final results) stay on the bus for a while.
  using Instances = std::set<std::pair<bus::Topic, std::string>>;  // (topic, subkey) of a job
  struct Kept {
    std::string job_id;
    Instances outputs;  // final results; empty for an intermediate stage
    std::uint64_t bytes = 0;
    Clock::time_point over;
  };

  const std::string& me() const { return presence.info().worker_id; }

  void publish_status(wire::JobStatus status) {
    status.stage = spec.stage;
    status.worker_id = me();
    const std::string subkey = status.job_id.empty() ? spec.stage + "/" + me() : spec.stage;
    const std::string bytes = wire::encode_status(status);
    status_writer.write(status.job_id, subkey, status_seq, static_cast<std::uint32_t>(status.state), false, bytes);
    if (!status.job_id.empty() && ends_job(status)) {
      over_writer.write(status.job_id, subkey, status_seq, static_cast<std::uint32_t>(status.state), false, bytes);
      with_over_status.insert(status.job_id);
    }
    ++status_seq;
    if (!status.job_id.empty()) with_status.insert(status.job_id);
  }

  static bool ends_job(const wire::JobStatus& s) {
    return s.state == wire::JobState::Error || s.state == wire::JobState::Cancelled ||
           (s.state == wire::JobState::Done && s.stage == bus::kStageStepWriter);
  }

  void health(const std::string& message) {
    wire::JobStatus s;
    s.state = wire::JobState::Running;
    s.message = message;
    publish_status(std::move(s));
  }

  void take_inputs() {
    for (auto& [in, reader] : inputs) {
      for (;;) {
        const std::vector<bus::Received> got = reader.take(std::chrono::milliseconds(0));
        for (const bus::Received& r : got) {
          if (!r.has_data) continue;
          const std::string job_id =
              in.job_id_includes_subkey ? r.envelope.key + "/" + r.envelope.subkey : r.envelope.key;
          assembler.add(in.topic, job_id, r.envelope);
        }
        if (got.size() < 256) break;
      }
    }
  }

  void take_statuses() {
    for (const bus::Received& r : status_reader.take(std::chrono::milliseconds(0), 4096)) {
      if (!r.has_data || r.envelope.key.empty()) continue;
      wire::JobStatus s;
      try {
        s = wire::decode_status(r.envelope.payload);
      } catch (const InputError& e) {
        spdlog::warn("ignoring a malformed status sample of job {}: {}", r.envelope.key, e.what());
        continue;
      }
      if (s.state == wire::JobState::Cancelled) {
        cancel(r.envelope.key, s);
        continue;
      }
      if (ends_job(s)) job_over(r.envelope.key);
      if (s.state == wire::JobState::Delivered) release_results(r.envelope.key);
    }
  }

  void job_over(const std::string& job_id) {
    if (assembler.finished(job_id)) return;
    assembler.finish(job_id);
    if (active.contains(job_id)) {
      spdlog::info("job {}: over elsewhere, stopped here", job_id);
      remember_published(job_id);
      announce_jobs();
    }
    started.erase(job_id);
    Kept kept{job_id, {}, 0, Clock::now()};
    if (const auto p = published.find(job_id); p != published.end()) {
      if (spec.unregister_output_when_over) {
        for (const auto& [topic, subkey] : p->second.first) unregister(writer_of(topic), job_id, subkey);
      } else {
        kept.outputs = std::move(p->second.first);
        kept.bytes = p->second.second;
      }
      published.erase(p);
    }
    const bool was_delivered = delivered.erase(job_id) != 0;
    if (with_status.erase(job_id) != 0 || !kept.outputs.empty()) {
      kept_bytes += kept.bytes;
      kept_jobs.push_back(std::move(kept));
      if (was_delivered) release(kept_jobs.back());
    }
  }

  // `ncbridge cancel` (a Cancelled status of stage "client"): the job is over here too, and the
  // worker that had it (started, or owns its input) says Cancelled in its stage, so `status`
  // shows it after the cancelling client is gone. A job over already stays as it ended. A job
  // running here stops between two of its input samples; work on one sample is not interrupted
  // (a whole-input stage's job then ends at the next stage).
  void cancel(const std::string& job_id, const wire::JobStatus& request) {
    if (assembler.finished(job_id)) return;
    const bool had = started.contains(job_id) ||
                     (assembler.known(job_id) && directory.tracker().owns(spec.stage, me(), job_id));
    if (had && request.stage == bus::kStageClient) {
      spdlog::info("job {}: cancelled", job_id);
      wire::JobStatus cancelled;
      cancelled.job_id = job_id;
      cancelled.state = wire::JobState::Cancelled;
      cancelled.message = request.message.empty() ? "cancelled" : request.message;
      publish_status(std::move(cancelled));
    }
    job_over(job_id);
  }

  // A client has the job's whole file: the results kept for it leave the bus now (each reader
  // that comes later would be sent every file kept); its statuses stay, under the retention policy.
  void release_results(const std::string& job_id) {
    if (published.contains(job_id)) {  // not over here yet (the client saw the last piece first)
      delivered.insert(job_id);
      return;
    }
    for (Kept& k : kept_jobs) {
      if (k.job_id == job_id) release(k);
    }
  }

  void release(Kept& k) {
    if (k.outputs.empty()) return;
    for (const auto& [topic, subkey] : k.outputs) unregister(writer_of(topic), k.job_id, subkey);
    spdlog::debug("job {}: result delivered, {} bytes released", k.job_id, k.bytes);
    k.outputs.clear();
    kept_bytes -= std::exchange(k.bytes, 0);
  }

  bus::SampleWriter& writer_of(bus::Topic topic) {
    for (auto& w : other_outputs) {
      if (w->topic() == topic) return *w;
    }
    return *output;
  }

  static void unregister(bus::SampleWriter& writer, const std::string& key, const std::string& subkey) {
    try {
      writer.unregister(key, subkey);
    } catch (const std::exception& e) {
      spdlog::warn("job {}: cannot unregister its {} sample: {}", key, subkey, e.what());
    }
  }

  // The retention policy: the oldest jobs over leave the bus first.
  void evict_kept() {
    const Retention& r = options.retention;
    const auto now = Clock::now();
    while (!kept_jobs.empty() &&
           (kept_jobs.size() > r.max_jobs || now - kept_jobs.front().over > r.max_age || kept_bytes > r.max_result_bytes)) {
      Kept& k = kept_jobs.front();
      for (const auto& [topic, subkey] : k.outputs) unregister(writer_of(topic), k.job_id, subkey);
      unregister(status_writer, k.job_id, spec.stage);
      if (with_over_status.erase(k.job_id) != 0) unregister(over_writer, k.job_id, spec.stage);
      kept_bytes -= k.bytes;
      kept_jobs.pop_front();
    }
  }

  // The jobs in progress, on the workers topic: at most once a second (every process reads that
  // topic; one announcement per job start and end made it the bus's busiest at many workers).
  void announce_jobs() { jobs_changed = true; }

  void flush_announcement() {
    const auto now = Clock::now();
    if (!jobs_changed || now - last_announced < std::chrono::seconds(1)) return;
    std::vector<std::string> ids;
    ids.reserve(active.size());
    for (const auto& [id, a] : active) ids.push_back(id);
    presence.update_jobs(std::move(ids));
    jobs_changed = false;
    last_announced = now;
  }

  bool can_start(const std::string& job_id) const {
    if (started.contains(job_id)) return false;
    // A whole-input stage takes a job once all of it is here; a streaming one at its first sample.
    if (spec.open ? !assembler.ready(job_id) : !assembler.complete(job_id)) return false;
    // A job input came to this worker because its publisher made it the owner.
    if (bus::routed_to(assembler.key(job_id)->topic)) return true;
    return directory.tracker().owns(spec.stage, me(), job_id);
  }

  void start_owned_jobs() {
    bool changed = false;
    for (const std::string& job_id : assembler.jobs()) {
      if (!can_start(job_id)) continue;
      start(job_id);
      changed = true;
    }
    if (changed) announce_jobs();
  }

  void start(const std::string& job_id) {
    started.insert(job_id);
    const JobKey key = *assembler.key(job_id);
    Active a;
    a.start = a.last_progress = Clock::now();
    Active* slot = nullptr;
    auto progress = [this, job_id](double fraction) {
      const auto it = active.find(job_id);
      if (it == active.end()) return;
      const auto now = Clock::now();
      if (now - it->second.last_progress < std::chrono::milliseconds(200)) return;
      it->second.last_progress = now;
      wire::JobStatus p;
      p.job_id = job_id;
      p.state = wire::JobState::Progress;
      p.progress = fraction;
      publish_status(std::move(p));
    };
    std::vector<bus::SampleWriter*> writers{output.get()};
    for (auto& w : other_outputs) writers.push_back(w.get());
    a.context = std::make_unique<JobContext>(std::move(writers), job_id, progress, options.max_job_time);
    slot = &active.emplace(job_id, std::move(a)).first->second;
    spdlog::info("job {}: started", job_id);
    wire::JobStatus running;
    running.job_id = job_id;
    running.state = wire::JobState::Running;
    publish_status(running);
    attempt(job_id, [&] {
      slot->stream = spec.open ? spec.open(key, *slot->context)
                               : std::make_unique<CollectingStream>(key, *slot->context, spec.run);
    });
  }

  // Feeds every active job what has come for it; finishes those whose last sample came.
  void feed_active() {
    std::vector<std::string> ids;
    for (const auto& [id, a] : active) ids.push_back(id);
    for (const std::string& job_id : ids) {
      const auto it = active.find(job_id);
      if (it == active.end() || !it->second.stream) continue;
      JobStream& stream = *it->second.stream;
      const JobContext& context = *it->second.context;
      std::vector<bus::Envelope> samples = assembler.take_ready(job_id);
      if (!attempt(job_id, [&] {
            context.check_time();  // also while it waits for input
            for (bus::Envelope& s : samples) {
              stream.sample(std::move(s));
              context.check_time();
            }
          }))
        continue;
      if (assembler.taken_all(job_id) && attempt(job_id, [&] { stream.finish(); })) done(job_id);
    }
  }

  // Runs part of a job's work; an exception ends the job with an ERROR status (false).
  template <class Work>
  bool attempt(const std::string& job_id, Work&& work) {
    try {
      work();
      return true;
    } catch (const InputError& e) {
      spdlog::warn("job {}: {}", job_id, e.what());
      fail(job_id, wire::error_status(job_id, spec.stage, me(), e));
    } catch (const std::exception& e) {
      spdlog::error("job {}: {}", job_id, e.what());
      wire::JobStatus end;
      end.job_id = job_id;
      end.state = wire::JobState::Error;
      end.message = e.what();
      fail(job_id, std::move(end));
    }
    return false;
  }

  void fail(const std::string& job_id, wire::JobStatus status) {
    remember_published(job_id);
    publish_status(std::move(status));
    job_over(job_id);
  }

  void done(const std::string& job_id) {
    const auto it = active.find(job_id);
    spdlog::info("job {}: done in {:.1f} ms", job_id,
                 std::chrono::duration<double, std::milli>(Clock::now() - it->second.start).count());
    remember_published(job_id);
    wire::JobStatus end;
    end.job_id = job_id;
    end.state = wire::JobState::Done;
    end.progress = 1;
    publish_status(end);
    active.erase(job_id);
    announce_jobs();
  }

  void remember_published(const std::string& job_id) {
    const auto it = active.find(job_id);
    if (it == active.end()) return;
    auto& [instances, bytes] = published[job_id];
    const JobContext& c = *it->second.context;
    instances.insert(c.published().begin(), c.published().end());
    bytes += c.published_bytes();
    active.erase(it);
  }

  StageSpec spec;
  RunnerOptions options;
  bus::WorkerPresence presence;
  bus::WorkerDirectory directory;
  bus::Reader status_reader;  // the statuses that end a job only (kJobOverPartition)
  bus::Writer status_writer;
  bus::Writer over_writer;    // those this worker publishes, again in kJobOverPartition
  std::unique_ptr<bus::SampleWriter> output;
  std::vector<std::unique_ptr<bus::SampleWriter>> other_outputs;
  std::vector<std::pair<InputTopic, bus::Reader>> inputs;
  bus::WaitSet wait_set;  // declared after the readers: detached before they go
  JobAssembler assembler;
  std::map<std::string, Active, std::less<>> active;
  std::set<std::string, std::less<>> started;       // jobs this worker started (never twice)
  // Jobs this worker published output for, with the subkeys and bytes, until they are over.
  std::map<std::string, std::pair<Instances, std::uint64_t>, std::less<>> published;
  std::set<std::string, std::less<>> with_status;   // jobs this worker published a status of
  std::set<std::string, std::less<>> with_over_status;  // ... and a status ending it
  std::set<std::string, std::less<>> delivered;  // jobs a client has whole before they were over here
  std::deque<Kept> kept_jobs;
  std::uint64_t kept_bytes = 0;
  std::uint64_t status_seq = 0;
  bool jobs_changed = false;
  Clock::time_point last_announced{};
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
    s.wait_set.wait(settled ? s.options.idle : std::chrono::milliseconds(20));
    s.take_inputs();
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
    s.start_owned_jobs();
    s.feed_active();
    s.evict_kept();
    s.flush_announcement();
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
