#include <gtest/gtest.h>

#include "ncbridge/common/error.hpp"
#include "ncbridge/wire/block.hpp"
#include "ncbridge/wire/job.hpp"
#include "ncbridge/wire/part21.hpp"
#include "ncbridge/wire/status.hpp"
#include "ncbridge/wire/worker.hpp"

using namespace ncbridge;
using namespace ncbridge::wire;

TEST(WireJob, RoundTripsToolsStockAndSetup) {
  const setup::ToolList tools = setup::parse_tool_list(
      R"([{"number": 1, "type": "flat_end_mill", "diameter": 10, "length": 50, "flutes": 3},
          {"number": 4, "type": "drill", "diameter": 6.8, "point_angle": 118, "name": "HSS \u00f8 6.8"}])",
      "tools.json");
  Job job;
  job.job_id = "j-42";
  job.file_name = "plate \xe9.ngc";
  job.program_text = "G21 G90\nG0 X0 Y0 (\xb0 latin-1)\nM30\n";
  job.dialect = Dialect::Fanuc;
  job.tools = tools.tools();
  job.stock = setup::Stock{{-3, 0, 0}, {100, 83, 32}};
  job.subroutine_path = {"/lib/subs", "subs2"};
  job.level = ConformanceClass::Cc2;
  const Job back = decode_job(encode_job(job));
  EXPECT_EQ(back.job_id, job.job_id);
  EXPECT_EQ(back.file_name, job.file_name);
  EXPECT_EQ(back.program_text, job.program_text);
  EXPECT_EQ(back.dialect, Dialect::Fanuc);
  ASSERT_EQ(back.tools.size(), 2u);
  EXPECT_EQ(back.tools[1].number, 4);
  EXPECT_EQ(back.tools[1].type, setup::ToolType::Drill);
  EXPECT_EQ(back.tools[1].name, tools.tools()[1].name);
  EXPECT_DOUBLE_EQ(back.tools[1].point_angle, 118);
  EXPECT_EQ(back.tools[0].flutes, 3);
  ASSERT_TRUE(back.stock.has_value());
  EXPECT_EQ(back.stock->min, job.stock->min);
  EXPECT_EQ(back.stock->max, job.stock->max);
  EXPECT_EQ(back.subroutine_path, job.subroutine_path);
  EXPECT_EQ(back.level, ConformanceClass::Cc2);

  job.stock.reset();
  EXPECT_FALSE(decode_job(encode_job(job)).stock.has_value());
}

TEST(WireJob, MalformedIsRejected) {
  const std::string bytes = encode_job({"j", "f.ngc", "G0 X1\n", Dialect::Rs274Ngc, {}, std::nullopt, {}, {}});
  EXPECT_THROW(decode_job(bytes.substr(0, bytes.size() - 2)), InputError);
  EXPECT_THROW(decode_job(std::string("\x20\x09", 2)), InputError);  // dialect = 9
}

TEST(WireBlock, RoundTrip) {
  const ExecutedBlock b{"mill-3", "run-2024-05-01T10:00", 17, BlockKind::Block, "N170 G1 X10 F300", 170};
  EXPECT_EQ(decode_block(encode_block(b)), b);
  ExecutedBlock start = b;
  start.kind = BlockKind::RunStart;
  EXPECT_EQ(decode_block(encode_block(start)).kind, BlockKind::RunStart);
  start.program_text = "G21\nG0 X1\nM2\n";
  start.tool_table = "T1 P1 Z1.5 D0.25\n";
  start.tool_table_inch = true;
  start.start_line = 12;
  EXPECT_EQ(decode_block(encode_block(start)), start);
  ExecutedBlock end = b;
  end.kind = BlockKind::RunEnd;
  end.aborted = true;
  end.reason = "the machine was e-stopped";
  EXPECT_EQ(decode_block(encode_block(end)), end);
  EXPECT_THROW(decode_block(std::string("\x20\x05", 2)), InputError);  // kind = 5
}

TEST(WireStatus, ErrorCarriesTheSourceLocation) {
  const InputError err({"part.ngc", 12, 5}, "unknown G code G12.7");
  const JobStatus s = decode_status(encode_status(error_status("j1", "interpreter", "w1", err)));
  EXPECT_EQ(s.state, JobState::Error);
  EXPECT_EQ(s.message, "unknown G code G12.7");
  EXPECT_EQ(s.where.file, "part.ngc");
  EXPECT_EQ(s.where.line, 12u);
  EXPECT_EQ(s.where.column, 5u);
  EXPECT_EQ(s.stage, "interpreter");

  JobStatus p{"j1", "cc1_builder", "w2", JobState::Progress, 0.25, "", {}};
  const JobStatus q = decode_status(encode_status(p));
  EXPECT_EQ(q.state, JobState::Progress);
  EXPECT_DOUBLE_EQ(q.progress, 0.25);
  EXPECT_TRUE(q.where.file.empty());
}

TEST(WireStatus, CancelledRoundTripsAndAStateBeyondItIsRefused) {
  const JobStatus c{"j2", "client", "", JobState::Cancelled, 0, "cancelled (ncbridge cancel)", {}};
  const JobStatus d = decode_status(encode_status(c));
  EXPECT_EQ(d.state, JobState::Cancelled);
  EXPECT_EQ(d.message, c.message);
  EXPECT_THROW(decode_status(std::string("\x20\x07", 2)), InputError);  // state = 7
}

TEST(WireWorker, RoundTrip) {
  const WorkerInfo w{"interpreter", "host-a/1234", "host-a", 1234, 1716000000123, {"j1", "j7"}};
  EXPECT_EQ(decode_worker(encode_worker(w)), w);
  EXPECT_THROW(decode_worker("\xff\xff\xff"), InputError);
}

TEST(WirePart21, RoundTripAndDigestLength) {
  Part21File f{"j9", Part21Level::Cc2, "j9_cc2.stp", "ISO-10303-21;\nHEADER;\n...", {}};
  for (std::size_t i = 0; i < f.sha256.size(); ++i) f.sha256[i] = static_cast<std::uint8_t>(i * 7);
  EXPECT_EQ(decode_part21(encode_part21(f)), f);
  f.seq = 41;  // a piece of a file, more to come
  f.more = true;
  EXPECT_EQ(decode_part21(encode_part21(f)), f);
  // A digest of the wrong length: job_id "j", sha256 (field 5) of 3 bytes.
  EXPECT_THROW(decode_part21(std::string("\x0a\x01j\x2a\x03\x01\x02\x03", 8)), InputError);
}
