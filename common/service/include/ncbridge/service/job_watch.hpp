#pragma once
// A client's view of its jobs (ncbridge submit --wait, controller-sim -o): their statuses as
// the stages report them, and each one's Part 21 file when the step_writer publishes it. Make
// the JobWatch before publishing the jobs; nothing is missed (status and part21 are durable too).
// One watch serves any number of jobs on one participant (a bulk submit).
#include <chrono>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/wait_set.hpp"
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
  JobWatch(bus::Participant& participant, std::vector<std::string> job_ids);

  // Waits up to `timeout` for the file (digest checked) or an error of the one job, handing every
  // status of it to `on_status` as it comes.
  JobOutcome wait(std::chrono::milliseconds timeout,
                  const std::function<void(const wire::JobStatus&)>& on_status = {});

  // Waits up to `timeout` until every job watched is over, handing each one's outcome to
  // `on_over` as it comes (so files need not all be held at once). Returns the jobs not over.
  std::set<std::string> wait_all(std::chrono::milliseconds timeout,
                                 const std::function<void(const std::string&, JobOutcome)>& on_over,
                                 const std::function<void(const wire::JobStatus&)>& on_status = {});

 private:
  std::set<std::string> pending_;
  bus::Reader status_;
  bus::Reader part21_;
  bus::WaitSet wait_set_;
};

}  // namespace ncbridge::service
