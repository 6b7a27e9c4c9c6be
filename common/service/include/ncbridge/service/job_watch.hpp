#pragma once
// A client's view of one job (ncbridge submit --wait, controller-sim --wait): its statuses as
// the stages report them, and its Part 21 file when the step_writer publishes it. Make the
// JobWatch before publishing the job; nothing is missed (status and part21 are durable too).
#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/wire/part21.hpp"
#include "ncbridge/wire/status.hpp"

namespace ncbridge::service {

struct JobOutcome {
  std::optional<wire::Part21File> file;   // set when the job is done
  std::optional<wire::JobStatus> error;   // set when a stage rejected it
  bool timed_out() const { return !file && !error; }
};

class JobWatch {
 public:
  JobWatch(bus::Participant& participant, std::string job_id);

  // Waits up to `timeout` for the file (digest checked) or an error, handing every status of the
  // job to `on_status` as it comes.
  JobOutcome wait(std::chrono::milliseconds timeout,
                  const std::function<void(const wire::JobStatus&)>& on_status = {});

 private:
  std::string job_id_;
  bus::Reader status_;
  bus::Reader part21_;
};

}  // namespace ncbridge::service
