// Job inputs go to their owner only (RoutedWriter, routing.hpp) over loopback DDS: each worker
// reads its own partition and gets exactly the jobs rendezvous hashing gives it; a worker that
// leaves has its jobs sent again to the survivor; a worker that joins takes only new jobs.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <optional>
#include <set>

#include "bus_environment.hpp"
#include "ncbridge/bus/bus_error.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/rendezvous.hpp"
#include "ncbridge/bus/routed_writer.hpp"
#include "ncbridge/bus/routing.hpp"
#include "ncbridge/bus/worker_presence.hpp"

using namespace ncbridge;
using namespace ncbridge::bus;
using namespace std::chrono_literals;
using ncbridge::test::BusEnvironment;

namespace {

const std::string kStage(kStageCc1Builder);

// One worker of the cc1_builder stage: its announcement and its reader of the canonical topic.
struct Worker {
  Worker(Participant& participant, const std::string& id)
      : presence(std::in_place, participant, info(id)),
        reader(participant, Topic::Canonical, worker_partition(kStage, id)) {}
  static wire::WorkerInfo info(const std::string& id) {
    wire::WorkerInfo w = this_process_worker(kStage);
    w.worker_id = id;
    return w;
  }
  std::optional<WorkerPresence> presence;
  Reader reader;
  std::map<std::string, std::vector<std::uint64_t>> got;  // job -> seqs received
  std::size_t samples = 0;
  void take() {
    for (const Received& r : reader.take(10ms)) {
      if (!r.has_data) continue;
      got[r.envelope.key].push_back(r.envelope.seq);
      ++samples;
    }
  }
};

// Takes on every worker until they hold `total` samples together, or 5 s.
void take_until(std::vector<Worker*> workers, std::size_t total) {
  const auto deadline = std::chrono::steady_clock::now() + 5s;
  for (;;) {
    std::size_t have = 0;
    for (Worker* w : workers) {
      w->take();
      have += w->samples;
    }
    if (have >= total || std::chrono::steady_clock::now() > deadline) return;
  }
}

std::string job(int i) { return "job-" + std::to_string(i); }

void write_job(RoutedWriter& writer, const std::string& id) {
  writer.write(id, "", 0, 1, false, "context of " + id);
  writer.write(id, "", 1, 2, true, "batch of " + id);
}

}  // namespace

TEST(Routing, OnlyJobInputsAreRouted) {
  EXPECT_EQ(routed_to(Topic::Programs), kStageInterpreter);
  EXPECT_EQ(routed_to(Topic::Canonical), kStageCc1Builder);
  EXPECT_EQ(routed_to(Topic::Workingsteps), kStageFeatureRecognizer);
  EXPECT_EQ(routed_to(Topic::Features), kStageStepWriter);
  for (Topic t : {Topic::Blocks, Topic::Part21, Topic::Status, Topic::Workers}) EXPECT_FALSE(routed_to(t));
  // Cyclone reads * and ? in a partition name as wildcards: a worker id cannot match another's.
  EXPECT_EQ(worker_partition("interpreter", "host/12"), "ncbridge.to.interpreter.host/12");
  EXPECT_EQ(worker_partition("interpreter", "a*?%"), "ncbridge.to.interpreter.a%2A%3F%25");
}

TEST(RoutedWriter, RefusesATopicEveryReaderGets) {
  BusEnvironment env;
  Participant participant(env.config);
  EXPECT_THROW(RoutedWriter(participant, Topic::Part21), BusError);
}

TEST(RoutedWriter, EachJobGoesToItsOwnerOnlyAndMovesWhenItsWorkerLeaves) {
  BusEnvironment env;
  Participant participant(env.config);
  Worker w1(participant, "w1"), w2(participant, "w2");
  RoutedWriter writer(participant, Topic::Canonical);
  std::mutex told_mutex;
  std::vector<std::string> told;
  writer.report_to([&](const std::string& m) {
    const std::lock_guard lock(told_mutex);
    told.push_back(m);
  });
  ASSERT_TRUE(writer.wait_for_readers(2, 5s));
  constexpr int kJobs = 24;
  for (int i = 0; i < kJobs; ++i) write_job(writer, job(i));
  take_until({&w1, &w2}, 2 * kJobs);

  const std::vector<std::string> both{"w1", "w2"};
  std::set<std::string> of_w1;
  for (int i = 0; i < kJobs; ++i) {
    const std::string owner = both[*rendezvous_owner(job(i), both)];
    Worker& mine = owner == "w1" ? w1 : w2;
    Worker& other = owner == "w1" ? w2 : w1;
    EXPECT_EQ(mine.got[job(i)], (std::vector<std::uint64_t>{0, 1})) << job(i) << " at its owner " << owner;
    EXPECT_FALSE(other.got.contains(job(i))) << job(i) << " reached a worker that does not own it";
    EXPECT_EQ(writer.worker_of(job(i)), owner);
    if (owner == "w1") of_w1.insert(job(i));
  }
  ASSERT_FALSE(of_w1.empty());
  ASSERT_LT(of_w1.size(), static_cast<std::size_t>(kJobs));
  EXPECT_EQ(writer.resent(), 0u);

  // w1 leaves (disposes its announcement): its jobs, every sample, go to w2; w2's stay.
  w1.presence.reset();
  w2.got.clear();
  w2.samples = 0;
  take_until({&w2}, 2 * of_w1.size());
  for (const std::string& id : of_w1) {
    EXPECT_EQ(w2.got[id], (std::vector<std::uint64_t>{0, 1})) << id << " was not sent again to w2";
    EXPECT_EQ(writer.worker_of(id), "w2");
  }
  EXPECT_EQ(w2.got.size(), of_w1.size()) << "w2 was sent again jobs it had";
  EXPECT_EQ(writer.resent(), 2 * of_w1.size());
  {
    const std::lock_guard lock(told_mutex);
    const std::string expected = "job " + *of_w1.begin() + ": 2 sample(s) of ncbridge/canonical sent again, to cc1_builder worker w2";
    EXPECT_NE(std::find(told.begin(), told.end(), expected), told.end()) << "not said: " << expected;
  }

  // Later samples of a moved job follow it; an unregistered job leaves the writer.
  writer.write(*of_w1.begin(), "", 2, 2, true, "more");
  w2.got.clear();
  w2.samples = 0;
  take_until({&w2}, 1);
  EXPECT_EQ(w2.got[*of_w1.begin()], (std::vector<std::uint64_t>{2}));
  writer.unregister(*of_w1.begin(), "");
  EXPECT_FALSE(writer.worker_of(*of_w1.begin()));
}

TEST(RoutedWriter, AWorkerThatJoinsTakesOnlyNewJobs) {
  BusEnvironment env;
  Participant participant(env.config);
  Worker w1(participant, "w1");
  RoutedWriter writer(participant, Topic::Canonical);
  ASSERT_TRUE(writer.wait_for_readers(1, 5s));
  for (int i = 0; i < 10; ++i) write_job(writer, job(i));
  take_until({&w1}, 20);
  EXPECT_EQ(w1.got.size(), 10u);

  Worker w2(participant, "w2");
  ASSERT_TRUE(writer.wait_for_readers(2, 5s));
  for (int i = 10; i < 40; ++i) write_job(writer, job(i));
  take_until({&w1, &w2}, 80);
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(writer.worker_of(job(i)), "w1") << job(i) << " moved to the worker that joined";
    EXPECT_FALSE(w2.got.contains(job(i)));
  }
  EXPECT_GT(w2.got.size(), 0u) << "the worker that joined got no new job";
  EXPECT_EQ(w1.got.size() + w2.got.size(), 40u);
}

TEST(RoutedWriter, KeepsJobsUntilAWorkerIsThere) {
  BusEnvironment env;
  Participant participant(env.config);
  RoutedWriter writer(participant, Topic::Canonical, 50ms);
  write_job(writer, job(1));
  EXPECT_FALSE(writer.wait_for_acks(300ms)) << "acknowledged with no worker to take the job";
  EXPECT_FALSE(writer.worker_of(job(1)));
  Worker w1(participant, "w1");
  take_until({&w1}, 2);
  EXPECT_EQ(w1.got[job(1)], (std::vector<std::uint64_t>{0, 1}));
  EXPECT_TRUE(writer.wait_for_acks(5s));
}
