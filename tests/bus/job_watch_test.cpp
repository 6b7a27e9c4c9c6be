// A client's JobWatch over loopback DDS: a file's pieces arrive out of order and twice (a redo
// by a second writer), are checked against their digests, and reach the client in order, either
// joined or piece by piece; a stage's error ends a job whose file had begun.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bus_environment.hpp"
#include "ncbridge/bus/writer.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/service/job_watch.hpp"
#include "ncbridge/service/sha256.hpp"
#include "ncbridge/wire/part21.hpp"
#include "ncbridge/wire/status.hpp"

using namespace ncbridge;
using namespace std::chrono_literals;
using ncbridge::test::BusEnvironment;

namespace {

wire::Part21File piece(const std::string& job, std::uint64_t seq, std::string content, bool more) {
  wire::Part21File p;
  p.job_id = job;
  p.file_name = job + ".stp";
  p.content = std::move(content);
  p.sha256 = service::sha256(p.content);
  p.seq = seq;
  p.more = more;
  return p;
}

void publish(bus::Writer& w, const wire::Part21File& p) { w.write(p.job_id, "cc1", p.seq, 0, !p.more, wire::encode_part21(p)); }

struct Rig {
  BusEnvironment env;
  bus::Participant participant{env.config};
  bus::Writer part21{participant, bus::Topic::Part21};
  bus::Writer status{participant, bus::Topic::Status};
};

}  // namespace

TEST(JobWatch, PiecesOutOfOrderAndRepeatedAreHandedOnInOrderOnce) {
  Rig rig;
  service::JobWatch watch(rig.participant, std::vector<std::string>{"job-a"});
  ASSERT_TRUE(rig.part21.wait_for_readers(1, 10s));
  for (const auto& p : {piece("job-a", 1, "second ", true), piece("job-a", 0, "first ", true),
                        piece("job-a", 0, "first ", true), piece("job-a", 2, "third", false)})
    publish(rig.part21, p);
  std::vector<std::uint64_t> order;
  std::string written;
  std::optional<service::JobOutcome> over;
  const auto late = watch.wait_all(
      10s,
      [&](const std::string& job, const wire::Part21File& p) {
        EXPECT_EQ(job, "job-a");
        order.push_back(p.seq);
        written += p.content;
      },
      [&](const std::string&, service::JobOutcome o) { over = std::move(o); });
  EXPECT_TRUE(late.empty());
  EXPECT_EQ(order, (std::vector<std::uint64_t>{0, 1, 2}));
  EXPECT_EQ(written, "first second third");
  ASSERT_TRUE(over && over->file);
  EXPECT_FALSE(over->file->more);
  EXPECT_EQ(over->file->seq, 2u);
  EXPECT_TRUE(over->file->content.empty());  // streamed: never joined in memory
}

TEST(JobWatch, WithoutAPieceHandlerTheFileIsJoined) {
  Rig rig;
  service::JobWatch watch(rig.participant, "job-b");
  ASSERT_TRUE(rig.part21.wait_for_readers(1, 10s));
  publish(rig.part21, piece("job-b", 1, "BB", false));
  publish(rig.part21, piece("job-b", 0, "AA", true));
  const service::JobOutcome o = watch.wait(10s);
  ASSERT_TRUE(o.file);
  EXPECT_EQ(o.file->content, "AABB");
  EXPECT_EQ(o.file->file_name, "job-b.stp");
}

TEST(JobWatch, APieceWhoseDigestDoesNotMatchIsAnError) {
  Rig rig;
  service::JobWatch watch(rig.participant, "job-c");
  ASSERT_TRUE(rig.part21.wait_for_readers(1, 10s));
  wire::Part21File bad = piece("job-c", 0, "ISO-10303-21;", false);
  bad.content[0] = 'X';
  publish(rig.part21, bad);
  EXPECT_THROW(watch.wait(10s), InputError);
}

TEST(JobWatch, AnErrorAfterTheFirstPiecesEndsTheJob) {
  Rig rig;
  service::JobWatch watch(rig.participant, std::vector<std::string>{"job-d"});
  ASSERT_TRUE(rig.status.wait_for_readers(1, 10s));
  publish(rig.part21, piece("job-d", 0, "begun", true));
  wire::JobStatus error;
  error.job_id = "job-d";
  error.stage = "step_writer";
  error.state = wire::JobState::Error;
  error.message = "disk full";
  int pieces = 0;
  std::optional<service::JobOutcome> over;
  const auto late = watch.wait_all(
      10s, [&](const std::string&, const wire::Part21File&) {
        ++pieces;
        rig.status.write("job-d", "step_writer", 0, static_cast<std::uint32_t>(wire::JobState::Error), false,
                         wire::encode_status(error));
      },
      [&](const std::string&, service::JobOutcome o) { over = std::move(o); });
  EXPECT_TRUE(late.empty());
  EXPECT_EQ(pieces, 1);
  ASSERT_TRUE(over && over->error);
  EXPECT_FALSE(over->file);
  EXPECT_EQ(over->error->message, "disk full");
}
