#include "ncbridge/bus/worker_tracker.hpp"

#include <gtest/gtest.h>

using namespace ncbridge::bus;

namespace {

Received sample(std::string stage, std::string worker, InstanceState state, bool has_data) {
  Received r;
  r.envelope.key = std::move(stage);
  r.envelope.subkey = std::move(worker);
  r.state = state;
  r.has_data = has_data;
  return r;
}

}  // namespace

TEST(WorkerTracker, AnnouncementsAndDeparturesFromTheWorkersTopic) {
  WorkerTracker t;
  EXPECT_TRUE(t.apply(sample("interpreter", "a/1", InstanceState::Alive, true)));
  EXPECT_TRUE(t.apply(sample("interpreter", "b/2", InstanceState::Alive, true)));
  EXPECT_FALSE(t.apply(sample("interpreter", "a/1", InstanceState::Alive, true)));  // re-announcement
  EXPECT_TRUE(t.apply(sample("cc1_builder", "a/3", InstanceState::Alive, true)));
  EXPECT_EQ(t.live_workers("interpreter"), (std::vector<std::string>{"a/1", "b/2"}));
  EXPECT_EQ(t.live_workers("cc1_builder"), (std::vector<std::string>{"a/3"}));
  EXPECT_TRUE(t.live_workers("step_writer").empty());

  EXPECT_TRUE(t.apply(sample("interpreter", "a/1", InstanceState::Disposed, false)));       // clean exit
  EXPECT_TRUE(t.apply(sample("cc1_builder", "a/3", InstanceState::NoWriters, false)));      // crash
  EXPECT_FALSE(t.apply(sample("cc1_builder", "a/3", InstanceState::NoWriters, false)));
  EXPECT_EQ(t.live_workers("interpreter"), (std::vector<std::string>{"b/2"}));
  EXPECT_TRUE(t.live_workers("cc1_builder").empty());
}

TEST(WorkerTracker, OwnershipFollowsMembership) {
  WorkerTracker t;
  EXPECT_FALSE(t.owner("interpreter", "job-1").has_value());
  for (const char* w : {"w1", "w2", "w3"}) t.alive("interpreter", w);
  const std::uint64_t gen = t.generation();
  int owned = 0;
  for (const char* w : {"w1", "w2", "w3"}) owned += t.owns("interpreter", w, "job-1") ? 1 : 0;
  EXPECT_EQ(owned, 1);  // exactly one worker takes a job
  const std::string first = *t.owner("interpreter", "job-1");
  t.gone("interpreter", first);
  EXPECT_GT(t.generation(), gen);
  const auto second = t.owner("interpreter", "job-1");
  ASSERT_TRUE(second.has_value());
  EXPECT_NE(*second, first);
  t.alive("interpreter", first);  // it comes back: the job goes back to it
  EXPECT_EQ(*t.owner("interpreter", "job-1"), first);
}

TEST(WorkerTracker, StagesAreIndependent) {
  WorkerTracker t;
  t.alive("interpreter", "x");
  EXPECT_FALSE(t.owns("cc1_builder", "x", "job"));
  EXPECT_TRUE(t.owns("interpreter", "x", "job"));
  EXPECT_FALSE(t.gone("cc1_builder", "x"));
}
