// JobAssembler: a job's samples complete exactly when seq 0..last are all there, duplicates
// (a redo after failover) are dropped, and a finished job's late samples are ignored.
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

TEST(JobAssembler, CompletesInSeqOrderWhateverTheArrivalOrder) {
  JobAssembler a;
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(2, true, "c")));
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(0, false, "a")));
  EXPECT_EQ(a.complete("job"), nullptr);
  EXPECT_TRUE(a.add(bus::Topic::Canonical, "job", sample(1, false, "b")));
  ASSERT_NE(a.complete("job"), nullptr);
  EXPECT_EQ(a.complete("job")->payloads, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(a.complete_jobs(), std::vector<std::string>{"job"});
}

TEST(JobAssembler, DropsDuplicatesOfARedo) {
  JobAssembler a;
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(0, false, "first")));
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(0, false, "redo")));  // same seq: dropped
  EXPECT_TRUE(a.add(bus::Topic::Canonical, "job", sample(1, true, "end")));
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(1, true, "end")));   // complete already
  EXPECT_EQ(a.complete("job")->payloads, (std::vector<std::string>{"first", "end"}));
}

TEST(JobAssembler, ForgetsFinishedJobsAndIgnoresTheirLateSamples) {
  JobAssembler a;
  EXPECT_TRUE(a.add(bus::Topic::Programs, "job", sample(0, true, "p")));
  a.finish("job");
  EXPECT_TRUE(a.finished("job"));
  EXPECT_EQ(a.complete("job"), nullptr);
  EXPECT_FALSE(a.add(bus::Topic::Programs, "job", sample(0, true, "p")));
  EXPECT_FALSE(a.known("job"));
}

TEST(JobAssembler, NeverCompletesWithAGapOrBeyondTheLast) {
  JobAssembler a;
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(0, false, "a")));
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(3, false, "stray")));
  EXPECT_FALSE(a.add(bus::Topic::Canonical, "job", sample(1, true, "b")));
  EXPECT_EQ(a.complete("job"), nullptr);  // seq 3 beyond the last: not a valid stream
}

}  // namespace
}  // namespace ncbridge::service
