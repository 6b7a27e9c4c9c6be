#pragma once
// A client's view of its jobs (ncbridge submit --wait, controller-sim -o): their statuses as
// the stages report them, and each one's Part 21 file when the step_writer publishes it. Make
// the JobWatch before publishing the jobs; nothing is missed (status and part21 are durable too).
// One watch serves any number of jobs on one participant (a bulk submit). When a file is whole
// the watch says so on the status topic (Delivered, stage "client"), and the step writer lets go
// of its copy.
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
#include "ncbridge/bus/writer.hpp"
#include "ncbridge/wire/part21.hpp"
#include "ncbridge/wire/status.hpp"

namespace ncbridge::service {

struct JobOutcome {
  // Set when the job is done: the file's pieces joined (each piece's digest checked; `sha256`
  // is that of the last piece, `more` false).
  std::optional<wire::Part21File> file;
  std::optional<wire::JobStatus> error;   // set when a stage rejected it, or it was cancelled
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

  // The same, but a file is never joined in memory: each piece (digest checked) goes to
  // `on_piece` as soon as the pieces before it have, so a client can write it out as it comes.
  // The outcome's `file` is then the last piece with its content emptied.
  using PieceHandler = std::function<void(const std::string& job_id, const wire::Part21File& piece)>;
  std::set<std::string> wait_all(std::chrono::milliseconds timeout, const PieceHandler& on_piece,
                                 const std::function<void(const std::string&, JobOutcome)>& on_over,
                                 const std::function<void(const wire::JobStatus&)>& on_status = {});

 private:
  // A file whose pieces are coming: the next piece expected, the joined pieces so far (when
  // joining), and those ahead of a gap.
  struct Incoming {
    std::uint64_t next = 0;
    std::optional<wire::Part21File> file;
    std::map<std::uint64_t, wire::Part21File> ahead;
  };
  // Adds a piece; hands the pieces now in order to `on_piece` (or joins them when it is empty)
  // and returns the file (joined, or the last piece emptied) when this piece completed it.
  std::optional<wire::Part21File> add_piece(wire::Part21File piece, const PieceHandler& on_piece);
  void say_delivered(const std::string& job_id);

  std::set<std::string> pending_;
  std::map<std::string, Incoming> incoming_;
  bus::Reader status_;
  bus::Reader part21_;
  bus::WaitSet wait_set_;
  bus::Writer delivered_;       // on the status topic
  bus::Writer delivered_over_;  // the same, in the partition the workers read (bus/routing.hpp)
};

}  // namespace ncbridge::service
