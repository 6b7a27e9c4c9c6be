// JobAssembler: a job's samples are handed over in seq order as soon as they are contiguous
// (streaming), whatever the arrival order; duplicates (a redo after failover) are dropped, also
// of samples already taken; a finished job's late samples are ignored, and the memory of
// finished jobs is bounded.
#include <gtest/gtest.h>

#include "ncbridge/service/job_assembler.hpp"

namespace ncbridge::service {
namespace {

bus::Envelope sample(std::uint64_t seq, bool last, std::string payload) {
  bus::Envelope e;
  e.key = "job";
  e.seq = seq;
  e.last = last;
  e.payload = std::move(payload);
  return e;
}

std::vector<std::string> payloads(const std::vector<bus::Envelope>& samples) {
  std::vector<std::string> out;
  for (const auto& s : samples) out.push_back(s.payload);
  return out;
}

TEST(JobAssembler, HandsOverContiguousSamplesInSeqOrderWhateverTheArrivalOrder) {
  JobAssembler a;
  EXPECT_TRUE(a.add(bus::Topic::Canonical, "job", sample(2, true, "c")));
  EXPECT_FALSE(a.ready("job"));
  EXPECT_TRUE(a.take_ready("job").empty());
  EXPECT_FALSE(a.complete("job"));
  EXPECT_TRUE(a.add(bus::Topic::Canonical, "job", sample(0, false, "a")));
  EXPECT_TRUE(a.ready("job"));
  EXPECT_EQ(payloads(a.take_ready("job")), std::vector<std::string>{"a"});  // 1 is missing: stop there
  EXPECT_FALSE(a.taken_all("job"));
  EXPECT_TRUE(a.add(bus::Topic::Canonical, "job", sample(1, false, "b")));
  EXPECT_TRUE(a.complete("job"));
  EXPECT_EQ(payloads(a.take_ready("job")), (std::vector<std::string>{"b", "c"}));
  EXPECT_TRUE(a.taken_all("job"));
  EXPECT_EQ(a.jobs(), std::vector<std::string>{"job"});
  EXPECT_EQ(a.key("job")->topic, bus::Topic::Canonical);
}

TEST(JobAssembler, DropsDuplicatesOfARedoAlsoOfSamplesTakenAlready) {
  JobAssembler a;
  EXPECT_TRUE(a.add(bus::Topic::Canonical, "job", sample(0, false, "first")));
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(0, false, "redo")));  // same seq: dropped
  EXPECT_EQ(payloads(a.take_ready("job")), std::vector<std::string>{"first"});
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(0, false, "redo")));  // taken already: dropped
  EXPECT_TRUE(a.add(bus::Topic::Canonical, "job", sample(1, true, "end")));
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(1, true, "end")));
  EXPECT_EQ(payloads(a.take_ready("job")), std::vector<std::string>{"end"});
  EXPECT_TRUE(a.taken_all("job"));
}

TEST(JobAssembler, AWorkerThatTakesNothingKeepsTheWholeInputForAFailover) {
  JobAssembler a;
  for (std::uint64_t seq = 0; seq < 5; ++seq) a.add(bus::Topic::Canonical, "job", sample(seq, seq == 4, std::to_string(seq)));
  EXPECT_TRUE(a.complete("job"));
  EXPECT_EQ(payloads(a.take_ready("job")), (std::vector<std::string>{"0", "1", "2", "3", "4"}));
}

TEST(JobAssembler, ForgetsFinishedJobsAndIgnoresTheirLateSamples) {
  JobAssembler a;
  EXPECT_TRUE(a.add(bus::Topic::Programs, "job", sample(0, true, "p")));
  a.finish("job");
  EXPECT_TRUE(a.finished("job"));
  EXPECT_FALSE(a.ready("job"));
  EXPECT_FALSE(a.add(bus::Topic::Programs, "job", sample(0, true, "p")));
  EXPECT_FALSE(a.known("job"));
}

TEST(JobAssembler, RemembersABoundedNumberOfFinishedJobs) {
  JobAssembler a(3);
  for (const char* id : {"j1", "j2", "j3", "j4"}) a.finish(id);
  EXPECT_FALSE(a.finished("j1"));  // the oldest is forgotten
  for (const char* id : {"j2", "j3", "j4"}) EXPECT_TRUE(a.finished(id)) << id;
}

TEST(JobAssembler, NeverCompletesWithAGapOrBeyondTheLast) {
  JobAssembler a;
  EXPECT_TRUE(a.add(bus::Topic::Canonical, "job", sample(0, false, "a")));
  EXPECT_TRUE(a.add(bus::Topic::Canonical, "job", sample(3, false, "stray")));
  EXPECT_TRUE(a.add(bus::Topic::Canonical, "job", sample(1, true, "b")));
  EXPECT_FALSE(a.complete("job"));  // seq 3 beyond the last: not a valid stream
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(5, false, "beyond")));
}

}  // namespace
}  // namespace ncbridge::service
