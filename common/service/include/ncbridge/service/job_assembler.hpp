#pragma once
// A job's input as it arrives: samples of one DDS instance numbered 0, 1, ... with the last one
// marked. Duplicates (same job, same seq: a redo after a failover, two workers of the stage
// before) are dropped, so the input is complete exactly when every seq up to the last is there.
// No DDS in here: feed it envelopes.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/bus/envelope.hpp"
#include "ncbridge/bus/topics.hpp"

namespace ncbridge::service {

struct JobInput {
  bus::Topic topic = bus::Topic::Programs;
  std::string job_id;
  std::string subkey;                  // the instance's subkey (blocks: the run id)
  std::vector<std::string> payloads;   // in seq order, one per sample
  std::vector<std::uint32_t> kinds;    // the envelopes' kind, beside each payload
};

class JobAssembler {
 public:
  // Adds one sample of `job_id`. Returns true when it completed the job's input. Samples of a
  // job already complete or finished are dropped (false).
  bool add(bus::Topic topic, const std::string& job_id, const bus::Envelope& sample);

  // The complete input of a job, or nullptr while samples are missing.
  const JobInput* complete(std::string_view job_id) const;
  // Jobs with a complete input, in the order they completed.
  std::vector<std::string> complete_jobs() const;
  bool known(std::string_view job_id) const;

  // The job is over (done or failed somewhere): its input is dropped and later samples of it
  // are ignored.
  void finish(const std::string& job_id);
  bool finished(std::string_view job_id) const { return finished_.contains(job_id); }

 private:
  struct Pending {
    JobInput input;
    std::map<std::uint64_t, bus::Envelope> samples;
    std::optional<std::uint64_t> last_seq;
    bool complete = false;
    std::uint64_t completed_order = 0;
  };
  std::map<std::string, Pending, std::less<>> jobs_;
  std::set<std::string, std::less<>> finished_;
  std::uint64_t completions_ = 0;
};

}  // namespace ncbridge::service
