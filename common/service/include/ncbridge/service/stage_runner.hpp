#pragma once
// The job loop every service runs around its stage library:
//  - reads the stage's input topics. A job input (programs, canonical, workingsteps, features)
//    comes to the worker that owns the job only: its publisher sends it in that worker's
//    partition (bus::RoutedWriter: rendezvous hashing over the live workers of the stage when the
//    job is first written; when the worker dies, the publisher sends the job to the survivor that
//    owns it now). A job's samples are de-duplicated and kept (JobAssembler) until it is over;
//  - a streaming stage (StageSpec::open) starts a job as soon as its first sample is there, and
//    gets the samples in seq order as they arrive; a whole-input stage (StageSpec::run) gets the
//    job once all of it is there. An input every worker reads (a controller's blocks) is started
//    by the worker that rendezvous hashing over the live workers of the stage ranks first, checked
//    again at every membership change, so a survivor takes over a dead worker's runs;
//  - publishes its output of a job the same way, to the owner in the next stage (a final result,
//    part21, to everyone), and keeps it until the job is over;
//  - publishes RUNNING, PROGRESS, DONE or ERROR (with the source location of an InputError) on
//    the status topic, and goes on with the next job after an error;
//  - reads the statuses that end a job (published again in bus::kJobOverPartition; a worker
//    does not read every RUNNING and PROGRESS): a job is over when the step_writer reports it
//    DONE or any stage reports an ERROR; its input is dropped, work on it stops, and this stage's output
//    instances of it are unregistered (which frees the writer's durable copy) — at once for an
//    intermediate stage, after the retention policy for final results (part21) and statuses;
//  - announces the worker (WorkerPresence) with its jobs in progress (at most once a second),
//    and its health as status samples with an empty job
//    id (subkey "<stage>/<worker_id>"): "ready" at start, "stopped" on a clean exit;
//  - stops a job that runs longer than RunnerOptions::max_job_time (--max-job-seconds) with an
//    ERROR status naming it, and goes on: the limit is checked between samples, on every
//    publish and progress report, and wherever a stage calls JobContext::check_time.
// The loop sleeps on one wait set over all its readers: no polling while idle.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/topics.hpp"
#include "ncbridge/bus/writer.hpp"
#include "ncbridge/service/job_assembler.hpp"
#include "ncbridge/service/shutdown_signal.hpp"

namespace ncbridge::service {

// One input topic of a stage. A job is one DDS instance: its id is the instance's key, or
// "key/subkey" when the subkey names the job's stream (blocks: controller_id/run_id).
struct InputTopic {
  bus::Topic topic;
  bool job_id_includes_subkey = false;
};

// A whole job's input, for stages that need all of it (StageSpec::run).
struct JobInput {
  bus::Topic topic = bus::Topic::Programs;
  std::string job_id;
  std::string subkey;
  std::vector<std::string> payloads;   // in seq order, one per sample
  std::vector<std::uint32_t> kinds;    // the envelopes' kind, beside each payload
};

// Thrown by JobContext::check_time once a job has run longer than its worker allows.
class JobTimeLimit : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a stage's work on one job gets besides its input.
class JobContext {
 public:
  using Progress = std::function<void(double)>;
  using Clock = std::chrono::steady_clock;
  // `outputs`: the stage's output topic first, then any others it may publish on. A job given a
  // `time_limit` (> 0) may run that long from now.
  JobContext(std::vector<bus::SampleWriter*> outputs, std::string job_id, Progress progress,
             std::chrono::milliseconds time_limit = std::chrono::milliseconds(0))
      : outputs_(std::move(outputs)), job_id_(std::move(job_id)), progress_(std::move(progress)),
        started_(Clock::now()), time_limit_(time_limit) {}

  // Throws JobTimeLimit (naming the job and the limit) once the job has run longer than its
  // time limit. Called by the runner between samples and by publish and progress; a stage whose
  // work between those can be long calls it as it goes (the recogniser between layers).
  void check_time() const;

  // Publishes one sample of this job on the stage's output topic (key = the job id).
  void publish(std::string_view subkey, std::uint64_t seq, std::uint32_t kind, bool last, std::string_view payload) {
    publish_on(outputs_.front()->topic(), subkey, seq, kind, last, payload);
  }
  // The same on another of the stage's outputs (StageSpec::other_outputs).
  void publish_on(bus::Topic topic, std::string_view subkey, std::uint64_t seq, std::uint32_t kind, bool last,
                  std::string_view payload);
  void progress(double fraction) {  // 0..1; rate-limited by the runner
    check_time();
    progress_(fraction);
  }
  const std::string& job_id() const { return job_id_; }

  // The instances (topic, subkey) this job published, and how many payload bytes.
  const std::set<std::pair<bus::Topic, std::string>>& published() const { return published_; }
  std::uint64_t published_bytes() const { return bytes_; }

 private:
  std::vector<bus::SampleWriter*> outputs_;
  std::string job_id_;
  Progress progress_;
  Clock::time_point started_;
  std::chrono::milliseconds time_limit_;
  std::set<std::pair<bus::Topic, std::string>> published_;
  std::uint64_t bytes_ = 0;
};

// A streaming stage's work on one job: the job's samples one by one in seq order (each once,
// duplicates dropped), then finish() after the one marked last. Throw InputError for bad input.
class JobStream {
 public:
  virtual ~JobStream() = default;
  virtual void sample(bus::Envelope sample) = 0;
  virtual void finish() = 0;
};

struct StageSpec {
  std::string stage;                  // bus::kStage*
  std::vector<InputTopic> inputs;
  bus::Topic output;                  // where the stage publishes
  std::vector<bus::Topic> other_outputs;  // where else it may (JobContext::publish_on)
  bool unregister_output_when_over = true;  // false for final results (part21): kept by retention
  // One of the two. run: gets a complete job. open: starts a job from its first sample (the
  // context outlives the stream). Both throw InputError for bad input (program, payload);
  // anything else thrown is reported as an error of the job too.
  std::function<void(const JobInput&, JobContext&)> run;
  std::function<std::unique_ptr<JobStream>(const JobKey&, JobContext&)> open;
};

// How long a job's statuses and final results stay on the bus (durable) after it is over. The
// oldest go first (unregistered) once any bound is passed.
struct Retention {
  std::size_t max_jobs = 1000;
  std::chrono::seconds max_age{3600};
  std::uint64_t max_result_bytes = std::uint64_t{1} << 30;  // final results only
};

struct RunnerOptions {
  std::string worker_id;   // empty: host/pid
  // Longest sleep while nothing comes (then the loop checks retention and membership).
  std::chrono::milliseconds idle{200};
  // After start, how long to listen for the other workers of the stage before taking jobs.
  std::chrono::milliseconds settle{300};
  // Longest a job may run here, from its start (its first sample for a streaming stage); 0: no
  // limit. Over it the job ends with an ERROR status and the worker goes on.
  std::chrono::milliseconds max_job_time{std::chrono::minutes(10)};
  Retention retention;
};

class StageRunner {
 public:
  StageRunner(bus::Participant& participant, StageSpec spec, RunnerOptions options);
  ~StageRunner();
  StageRunner(const StageRunner&) = delete;
  StageRunner& operator=(const StageRunner&) = delete;

  // Runs until `shutdown` is requested; returns the process exit code (0).
  int run(ShutdownSignal& shutdown);

  const std::string& worker_id() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ncbridge::service
