#pragma once
// A client's view of its jobs (ncbridge submit --wait, controller-sim -o): their statuses as
// the stages report them, and each one's Part 21 file when the step_writer publishes it. Make
// the JobWatch before publishing the jobs; nothing is missed (status and part21 are durable too).
// One watch serves any number of jobs on one participant (a bulk submit).
#include <chrono>
#include <functional>
#include <map>
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
  // Set when the job is done: the file's pieces joined (each piece's digest checked; `sha256`
  // is that of the last piece, `more` false).
  std::optional<wire::Part21File> file;
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
  // A file whose pieces are coming: the joined pieces so far, and those ahead of a gap.
  struct Incoming {
    std::optional<wire::Part21File> file;
    std::map<std::uint64_t, wire::Part21File> ahead;
  };
  // Adds a piece; returns the whole file when this piece completed it.
  std::optional<wire::Part21File> add_piece(wire::Part21File piece);

  std::set<std::string> pending_;
  std::map<std::string, Incoming> incoming_;
  bus::Reader status_;
  bus::Reader part21_;
  bus::WaitSet wait_set_;
};

}  // namespace ncbridge::service
