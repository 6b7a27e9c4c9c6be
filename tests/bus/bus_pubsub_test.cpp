// The DDS bus over loopback: in one process, and across two real processes.
#include <gtest/gtest.h>

#include <csignal>
#include <map>

#include "bus_environment.hpp"
#include "canonical_samples.hpp"
#include "child_process.hpp"
#include "ncbridge/bus/canonical_batcher.hpp"
#include "ncbridge/bus/qos_profiles.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/worker_directory.hpp"
#include "ncbridge/bus/worker_presence.hpp"
#include "ncbridge/bus/writer.hpp"
#include "ncbridge/wire/status.hpp"

using namespace ncbridge;
using namespace ncbridge::bus;
using namespace std::chrono_literals;
using ncbridge::test::BusEnvironment;
using ncbridge::test::ChildProcess;

namespace {

// Takes until `count` data samples arrived or `timeout` ran out.
std::vector<Envelope> take_data(Reader& reader, std::size_t count, std::chrono::milliseconds timeout) {
  std::vector<Envelope> out;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (out.size() < count && std::chrono::steady_clock::now() < deadline) {
    for (Received& r : reader.take(50ms))
      if (r.has_data) out.push_back(std::move(r.envelope));
  }
  return out;
}

// Polls the directory until `done` holds or `timeout` runs out; returns `done`'s last value.
template <class Pred>
bool poll_until(WorkerDirectory& directory, std::chrono::milliseconds timeout, Pred done) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    directory.poll(50ms);
  }
  return true;
}

bool has_worker(const WorkerDirectory& d, const std::string& stage, const std::string& id) {
  for (const std::string& w : d.tracker().live_workers(stage))
    if (w == id) return true;
  return false;
}

}  // namespace

TEST(BusTopics, NamesAndProfiles) {
  EXPECT_EQ(topic_name(Topic::Canonical), "ncbridge/canonical");
  for (Topic t : kAllTopics) EXPECT_EQ(topic_name(t).substr(0, 9), "ncbridge/");
  for (Topic t : {Topic::Programs, Topic::Blocks, Topic::Canonical, Topic::Workingsteps, Topic::Features}) {
    EXPECT_EQ(qos_profile(t).durability, Durability::TransientLocal) << topic_name(t);
    EXPECT_EQ(qos_profile(t).reader_history, History::KeepAll) << topic_name(t);
    EXPECT_TRUE(qos_profile(t).reliable);
  }
  EXPECT_GE(qos_profile(Topic::Canonical).depth, 4096);
  EXPECT_GT(qos_profile(Topic::Workers).liveliness_lease.count(), 0);
  EXPECT_TRUE(qos_profile(Topic::Workers).autodispose_unregistered);
}

TEST(BusLoopback, CanonicalBatchesInOneProcess) {
  BusEnvironment env;
  Participant participant(env.config);
  Reader reader(participant, Topic::Canonical);
  Writer writer(participant, Topic::Canonical);
  ASSERT_TRUE(writer.wait_for_readers(1, 10s));
  CanonicalBatcher batcher("job-a", 100, [&](const Envelope& e) { writer.write(e); });
  for (std::size_t i = 0; i < 450; ++i) batcher.call(test::sample_call(i));
  batcher.end();
  const std::vector<Envelope> got = take_data(reader, 5, 10s);
  ASSERT_EQ(got.size(), 5u);
  std::size_t n = 0;
  for (std::size_t b = 0; b < got.size(); ++b) {
    EXPECT_EQ(got[b].key, "job-a");
    EXPECT_EQ(got[b].seq, b);
    EXPECT_EQ(got[b].last, b == 4);
    for (const canonical::Call& c : canonical::decode_batch(got[b].payload).calls)
      EXPECT_TRUE(test::same_call(c, test::sample_call(n++)));
  }
  EXPECT_EQ(n, 450u);
}

TEST(BusLoopback, LateReaderGetsTheWholeJobUntilItIsUnregistered) {
  BusEnvironment env;
  Participant participant(env.config);
  Writer writer(participant, Topic::Canonical);
  for (std::uint64_t s = 0; s < 50; ++s) writer.write("job-late", "", s, 0, s == 49, "payload " + std::to_string(s));
  writer.write("job-other", "", 0, 0, true, "other");
  {
    Reader late(participant, Topic::Canonical);
    const std::vector<Envelope> got = take_data(late, 51, 10s);
    ASSERT_EQ(got.size(), 51u);
    std::map<std::string, std::uint64_t> next_seq;
    for (const Envelope& e : got) {
      EXPECT_EQ(e.seq, next_seq[e.key]++) << e.key;  // in order within a job
      if (e.key == "job-late") {
        EXPECT_EQ(e.payload, "payload " + std::to_string(e.seq));
      }
    }
    EXPECT_EQ(next_seq["job-late"], 50u);
  }
  writer.unregister("job-late", "");
  Reader later(participant, Topic::Canonical);
  const std::vector<Envelope> got = take_data(later, 2, 1s);
  ASSERT_EQ(got.size(), 1u);  // only the job still in flight
  EXPECT_EQ(got[0].key, "job-other");
}

TEST(BusLoopback, StatusKeepsTheLatestPerJobAndStage) {
  BusEnvironment env;
  Participant participant(env.config);
  Writer writer(participant, Topic::Status);
  for (int i = 0; i <= 4; ++i) {
    wire::JobStatus s{"job-s", "interpreter", "w", wire::JobState::Progress, i / 4.0, "", {}};
    writer.write("job-s", "interpreter", static_cast<std::uint64_t>(i), 0, false, wire::encode_status(s));
  }
  // Same job, another stage: another instance (both keys count).
  writer.write("job-s", "cc1_builder", 0, 0, false,
               wire::encode_status({"job-s", "cc1_builder", "w", wire::JobState::Queued, 0, "", {}}));
  Reader late(participant, Topic::Status);
  const std::vector<Envelope> got = take_data(late, 3, 1s);
  ASSERT_EQ(got.size(), 2u);
  std::map<std::string, double> progress;
  for (const Envelope& e : got) progress[e.subkey] = wire::decode_status(e.payload).progress;
  EXPECT_DOUBLE_EQ(progress.at("interpreter"), 1.0);
  EXPECT_DOUBLE_EQ(progress.at("cc1_builder"), 0.0);
}

TEST(BusLoopback, WorkerPresenceComesAndGoes) {
  BusEnvironment env;
  Participant participant(env.config);
  WorkerDirectory directory(participant);
  auto presence = std::make_unique<WorkerPresence>(participant, this_process_worker("cc1_builder"));
  const std::string id = presence->info().worker_id;
  ASSERT_TRUE(poll_until(directory, 10s, [&] { return has_worker(directory, "cc1_builder", id); }));
  EXPECT_EQ(*directory.owner("cc1_builder", "any-job"), id);
  presence.reset();  // a clean exit disposes the instance
  EXPECT_TRUE(poll_until(directory, 10s, [&] { return !has_worker(directory, "cc1_builder", id); }));
  EXPECT_FALSE(directory.owner("cc1_builder", "any-job").has_value());
}

TEST(BusLoopback, TakeTimesOutWhenNothingComes) {
  BusEnvironment env;
  Participant participant(env.config);
  Reader reader(participant, Topic::Features);
  EXPECT_TRUE(reader.take(100ms).empty());
}

TEST(BusTwoProcesses, CanonicalStreamFromAnotherProcess) {
  BusEnvironment env;
  Participant participant(env.config);
  Reader reader(participant, Topic::Canonical);
  ChildProcess peer({NCBRIDGE_BUS_TEST_PEER, "publish", std::to_string(env.config.domain_id),
                     env.config.cyclonedds_uri, "job-remote", "5000", "512"});
  const std::vector<Envelope> got = take_data(reader, 10, 30s);
  ASSERT_EQ(got.size(), 10u);  // 5000 calls / 512 a batch
  std::size_t n = 0;
  for (std::size_t b = 0; b < got.size(); ++b) {
    EXPECT_EQ(got[b].seq, b);
    const canonical::DecodedBatch batch = canonical::decode_batch(got[b].payload);
    EXPECT_EQ(batch.job_id, "job-remote");
    if (b == 0) {
      EXPECT_EQ(batch.files.size(), 1u);
    }
    for (const canonical::Call& c : batch.calls) ASSERT_TRUE(test::same_call(c, test::sample_call(n++))) << n;
  }
  EXPECT_EQ(n, 5000u);
  EXPECT_TRUE(got.back().last);
  EXPECT_EQ(peer.wait(30s), 0);
}

TEST(BusTwoProcesses, KilledWorkerVanishesWithinTheLease) {
  BusEnvironment env(1000ms);
  Participant participant(env.config);
  WorkerDirectory directory(participant);
  ChildProcess peer({NCBRIDGE_BUS_TEST_PEER, "worker", std::to_string(env.config.domain_id),
                     env.config.cyclonedds_uri, "interpreter", "doomed/1", "60"});
  ASSERT_TRUE(poll_until(directory, 20s, [&] { return has_worker(directory, "interpreter", "doomed/1"); }));
  peer.signal(SIGKILL);
  ASSERT_EQ(peer.wait(5s), 128 + SIGKILL);
  // Lease 1 s: gone well before Cyclone's default 10 s lease would have noticed.
  EXPECT_TRUE(poll_until(directory, 5s, [&] { return !has_worker(directory, "interpreter", "doomed/1"); }));
}

TEST(BusTwoProcesses, WorkerLeavingCleanlyIsDisposed) {
  BusEnvironment env;
  Participant participant(env.config);
  WorkerDirectory directory(participant);
  ChildProcess a({NCBRIDGE_BUS_TEST_PEER, "worker", std::to_string(env.config.domain_id), env.config.cyclonedds_uri,
                  "step_writer", "a/1", "60"});
  ChildProcess b({NCBRIDGE_BUS_TEST_PEER, "worker", std::to_string(env.config.domain_id), env.config.cyclonedds_uri,
                  "step_writer", "b/2", "60"});
  ASSERT_TRUE(poll_until(directory, 20s, [&] { return directory.tracker().live_workers("step_writer").size() == 2; }));
  // Of 100 jobs each worker owns some; when a leaves, b owns them all.
  int owned_by_a = 0;
  for (int j = 0; j < 100; ++j) owned_by_a += *directory.owner("step_writer", "job-" + std::to_string(j)) == "a/1";
  EXPECT_GT(owned_by_a, 20);
  EXPECT_LT(owned_by_a, 80);
  a.signal(SIGTERM);
  EXPECT_EQ(a.wait(10s), 0);
  ASSERT_TRUE(poll_until(directory, 10s, [&] { return !has_worker(directory, "step_writer", "a/1"); }));
  for (int j = 0; j < 100; ++j) EXPECT_EQ(*directory.owner("step_writer", "job-" + std::to_string(j)), "b/2");
}
