#pragma once
// Where a job stands in one stage: the ncbridge/status topic (proto/status.proto), and its codec.
#include <cstdint>
#include <string>
#include <string_view>

#include "ncbridge/common/error.hpp"

namespace ncbridge::wire {

// Delivered: a client has the job's whole file (stage "client"); the step writer then drops its
// copy from the bus, so readers that come later are not sent every file kept.
// Cancelled: a client asked to drop the job (stage "client", `ncbridge cancel`); the worker that
// had it drops it and says Cancelled in its own stage.
enum class JobState : std::uint8_t { Queued, Running, Progress, Done, Error, Delivered, Cancelled };

struct JobStatus {
  std::string job_id;
  std::string stage;
  std::string worker_id;
  JobState state = JobState::Queued;
  double progress = 0;       // 0..1
  std::string message;       // for Error: the user-level reason
  SourceLocation where;      // for Error: where in the user's input
};

std::string encode_status(const JobStatus& status);
JobStatus decode_status(std::string_view bytes);  // throws InputError on malformed bytes

// The status a stage publishes when it rejects a job's input.
JobStatus error_status(std::string job_id, std::string stage, std::string worker_id, const InputError& error);

}  // namespace ncbridge::wire
