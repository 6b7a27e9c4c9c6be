#pragma once
// A job's input as it arrives: samples of one DDS instance numbered 0, 1, ... with the last one
// marked. Duplicates (same job, same seq: a redo after a failover, two workers of the stage
// before) are dropped. Every worker of a stage keeps every job's samples, owner or not, so a
// survivor can redo a dead owner's job; the owner takes them as they become contiguous
// (take_ready) and works on the job while the rest is still coming (streaming).
// No DDS in here: feed it envelopes.
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/bus/envelope.hpp"
#include "ncbridge/bus/topics.hpp"

namespace ncbridge::service {

// Which job a stream belongs to.
struct JobKey {
  bus::Topic topic = bus::Topic::Programs;
  std::string job_id;
  std::string subkey;  // the instance's subkey (blocks: the run id)
};

class JobAssembler {
 public:
  // How many finished job ids are remembered (their late samples dropped); the oldest are
  // forgotten beyond it, so memory stays bounded on a service that runs for months.
  explicit JobAssembler(std::size_t remembered_finished = 100'000) : remembered_finished_(remembered_finished) {}

  // Adds one sample of `job_id`. Returns false when it was dropped: a duplicate, a sample
  // taken already, or one of a finished job.
  bool add(bus::Topic topic, const std::string& job_id, const bus::Envelope& sample);

  // Jobs with samples, in the order their first sample came.
  std::vector<std::string> jobs() const;
  const JobKey* key(std::string_view job_id) const;
  // True when the job's next sample to take is here.
  bool ready(std::string_view job_id) const;
  // The samples from the next one to take on, as long as they are contiguous; they leave the
  // assembler (later duplicates of them are dropped).
  std::vector<bus::Envelope> take_ready(std::string_view job_id);
  // True once the sample marked last was taken.
  bool taken_all(std::string_view job_id) const;
  // True when every sample up to the one marked last is here or taken.
  bool complete(std::string_view job_id) const;
  bool known(std::string_view job_id) const { return jobs_.contains(job_id); }

  // The job is over (done or failed somewhere): its samples are dropped and later samples of
  // it are ignored.
  void finish(const std::string& job_id);
  bool finished(std::string_view job_id) const { return finished_.contains(job_id); }

 private:
  struct Pending {
    JobKey key;
    std::map<std::uint64_t, bus::Envelope> samples;  // not taken yet
    std::uint64_t next = 0;                          // first seq not taken
    std::optional<std::uint64_t> last_seq;
    std::uint64_t arrival = 0;
  };
  std::map<std::string, Pending, std::less<>> jobs_;
  std::set<std::string, std::less<>> finished_;
  std::deque<std::string> finished_order_;
  std::size_t remembered_finished_;
  std::uint64_t arrivals_ = 0;
};

}  // namespace ncbridge::service
