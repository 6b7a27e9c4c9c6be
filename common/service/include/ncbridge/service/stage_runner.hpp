#pragma once
// The job loop every service runs around its stage library:
//  - reads the stage's input topics; a job's samples are assembled and de-duplicated
//    (JobAssembler) by EVERY worker of the stage, owner or not, so a survivor can redo a dead
//    worker's job from what it already holds;
//  - runs a complete job when rendezvous hashing over the live workers of the stage (workers
//    topic + DDS liveliness) ranks this worker first, and again whenever the membership changes;
//  - publishes RUNNING, PROGRESS, DONE or ERROR (with the source location of an InputError) on
//    the status topic, and goes on with the next job after an error;
//  - reads the status topic: a job is over when the step_writer reports it DONE or any stage
//    reports an ERROR; its input is dropped and this stage's output instance of it unregistered
//    (which frees the writer's durable copy).
//  - announces the worker (WorkerPresence), and its health as status samples with an empty job
//    id (subkey "<stage>/<worker_id>"): "ready" at start, "stopped" on a clean exit.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
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

// What a stage's run function gets besides its input.
class JobContext {
 public:
  JobContext(bus::Writer* output, std::function<void(double)> progress, const std::string& worker_id)
      : output_(output), progress_(std::move(progress)), worker_id_(worker_id) {}
  bus::Writer& output() { return *output_; }   // the stage's output topic
  void progress(double fraction) { progress_(fraction); }  // 0..1; rate-limited by the runner
  const std::string& worker_id() const { return worker_id_; }

 private:
  bus::Writer* output_;
  std::function<void(double)> progress_;
  const std::string& worker_id_;
};

struct StageSpec {
  std::string stage;                  // bus::kStage*
  std::vector<InputTopic> inputs;
  bus::Topic output;                  // where run() publishes
  bool unregister_output_when_over = true;  // false for final results (part21)
  // Runs one complete job. Throws InputError for bad input (program, payload); anything
  // else thrown is reported as an error of the job too.
  std::function<void(const JobInput&, JobContext&)> run;
};

struct RunnerOptions {
  std::string worker_id;   // empty: host/pid
  std::chrono::milliseconds poll{20};
  // After start, how long to listen for the other workers of the stage before taking jobs.
  std::chrono::milliseconds settle{300};
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
