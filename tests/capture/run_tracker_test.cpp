#include <gtest/gtest.h>

#include "ncbridge/capture/run_tracker.hpp"

using namespace ncbridge::capture;
using Interp = ControllerSample::Interp;

namespace {

const std::string kProgram =
    "G21 G90\n"          // 1
    "T1 M6\n"            // 2
    "S1000 M3\n"         // 3
    "G0 X0 Y0 Z5\n"      // 4
    "G1 Z-1 F100\n"      // 5
    "G1 X10\n"           // 6
    "G1 Y10\n"           // 7
    "G1 X0\n"            // 8
    "G0 Z5\n"            // 9
    "M5\n"               // 10
    "M2\n";              // 11

RunTracker tracker() {
  return RunTracker([](const std::string&) {
    RunProgram p;
    p.text = kProgram;
    p.order = execution_order("p.ngc", kProgram, {});
    p.tool_table = "T1 P1 Z50 D6\n";
    return p;
  });
}

ControllerSample at(Interp interp, std::uint32_t line) {
  ControllerSample s;
  s.interp = interp;
  s.program = "/nc/p.ngc";
  s.line = line;
  return s;
}

std::vector<RunEvent> feed(RunTracker& t, const std::vector<ControllerSample>& samples) {
  std::vector<RunEvent> all;
  for (const auto& s : samples) {
    for (auto& e : t.observe(s)) all.push_back(std::move(e));
  }
  return all;
}

std::vector<std::uint32_t> block_lines(const std::vector<RunEvent>& events) {
  std::vector<std::uint32_t> out;
  for (const auto& e : events) {
    if (e.kind == RunEvent::Kind::Block) out.push_back(e.line);
  }
  return out;
}

}  // namespace

TEST(RunTracker, ACompletedRunPublishesEveryBlockThoughFewLinesWereSeen) {
  RunTracker t = tracker();
  // motion seen on lines 4, 6 and 9 only; LinuxCNC keeps the last line when the program ends
  const auto events = feed(t, {at(Interp::Running, 4), at(Interp::Running, 6), at(Interp::Paused, 6),
                               at(Interp::Running, 9), at(Interp::Idle, 9)});
  ASSERT_GE(events.size(), 3u);
  EXPECT_EQ(events.front().kind, RunEvent::Kind::Start);
  EXPECT_EQ(events.front().text, "/nc/p.ngc");
  EXPECT_EQ(events.front().program_text, kProgram);
  EXPECT_EQ(events.front().tool_table, "T1 P1 Z50 D6\n");
  EXPECT_EQ(block_lines(events), (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(events.back().kind, RunEvent::Kind::End);
  EXPECT_FALSE(events.back().aborted);
  EXPECT_EQ(events.back().blocks, 11u);
  EXPECT_FALSE(t.running());
}

TEST(RunTracker, BlocksArePublishedAsMotionReachesThem) {
  RunTracker t = tracker();
  const auto first = t.observe(at(Interp::Running, 4));
  EXPECT_EQ(block_lines(first), (std::vector<std::uint32_t>{1, 2, 3, 4}));
  EXPECT_TRUE(block_lines(t.observe(at(Interp::Running, 4))).empty());  // nothing new
  EXPECT_EQ(block_lines(t.observe(at(Interp::Running, 7))), (std::vector<std::uint32_t>{5, 6, 7}));
}

TEST(RunTracker, AnAbortedRunEndsAbortedWithTheBlocksThatRan) {
  RunTracker t = tracker();
  const auto events = feed(t, {at(Interp::Running, 4), at(Interp::Running, 6), at(Interp::Idle, 0)});
  EXPECT_EQ(block_lines(events), (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 6}));
  ASSERT_EQ(events.back().kind, RunEvent::Kind::End);
  EXPECT_TRUE(events.back().aborted);
  EXPECT_NE(events.back().reason.find("line 6"), std::string::npos) << events.back().reason;
}

TEST(RunTracker, AFaultOrLeavingAutomaticModeAbortsTheRun) {
  RunTracker t = tracker();
  ControllerSample fault = at(Interp::Running, 6);
  fault.fault = true;
  fault.fault_reason = "e-stop";
  auto events = feed(t, {at(Interp::Running, 4), fault});
  EXPECT_TRUE(events.back().aborted);
  EXPECT_EQ(events.back().reason, "e-stop");

  RunTracker u = tracker();
  ControllerSample mdi = at(Interp::Running, 0);
  mdi.mode = ControllerSample::Mode::Mdi;
  events = feed(u, {at(Interp::Running, 5), mdi});
  EXPECT_TRUE(events.back().aborted);
}

TEST(RunTracker, MdiAndManualActivityStartsNoRun) {
  RunTracker t = tracker();
  ControllerSample mdi = at(Interp::Running, 0);
  mdi.mode = ControllerSample::Mode::Mdi;
  EXPECT_TRUE(t.observe(mdi).empty());
  EXPECT_FALSE(t.running());
}

TEST(RunTracker, AStartFromALaterLineKeepsTheModalBlocksBeforeIt) {
  RunTracker t = tracker();
  const auto events = feed(t, {at(Interp::Running, 8), at(Interp::Idle, 9)});
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.front().start_line, 8u);
  // 1-3 set units, tool and spindle; the moves 4-7 were not run
  EXPECT_EQ(block_lines(events), (std::vector<std::uint32_t>{1, 2, 3, 8, 9, 10, 11}));
  EXPECT_FALSE(events.back().aborted);
}

TEST(RunTracker, AShortFirstMoveMissedBetweenSamplesIsNoRestart) {
  RunTracker t = tracker();
  const auto events = feed(t, {at(Interp::Running, 5), at(Interp::Idle, 9)});
  EXPECT_EQ(events.front().start_line, 0u);
  EXPECT_EQ(block_lines(events).size(), 11u);
}

TEST(RunTracker, ControllerBlockTextsAreUsedWhenTheProgramIsUnknown) {
  RunTracker t([](const std::string&) { return RunProgram{}; });
  auto block = [](const char* text, Interp interp = Interp::Running) {
    ControllerSample s;
    s.interp = interp;
    s.program = "O1234";
    s.block = text;
    return s;
  };
  const auto events = feed(t, {block("G0 X0"), block("G0 X0"), block("G1 X5"), block("G1 X5", Interp::Idle)});
  ASSERT_EQ(events.size(), 4u);
  EXPECT_EQ(events[1].text, "G0 X0");
  EXPECT_EQ(events[2].text, "G1 X5");
  EXPECT_FALSE(events.back().aborted);

  RunTracker u([](const std::string&) { return RunProgram{}; });
  feed(u, {block("G0 X0")});
  const auto lost = u.gap("buffer overrun");
  ASSERT_EQ(lost.size(), 1u);
  EXPECT_TRUE(lost[0].aborted);
}

TEST(RunTracker, AGapInALineFollowingRunLosesNothing) {
  RunTracker t = tracker();
  feed(t, {at(Interp::Running, 4)});
  EXPECT_TRUE(t.gap("buffer overrun").empty());
  EXPECT_TRUE(t.running());
}

TEST(RunTracker, AProgramThatCannotBeReadEndsTheRunAborted) {
  RunTracker t([](const std::string&) -> RunProgram { throw std::runtime_error("no such file"); });
  const auto events = t.observe(at(Interp::Running, 3));
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, RunEvent::Kind::Start);
  EXPECT_TRUE(events[1].aborted);
  EXPECT_NE(events[1].reason.find("no such file"), std::string::npos);
  // the same execution goes on: it is not a new run; the next one after it stops is
  EXPECT_TRUE(t.observe(at(Interp::Running, 5)).empty());
  EXPECT_TRUE(t.observe(at(Interp::Idle, 0)).empty());
  EXPECT_EQ(t.observe(at(Interp::Running, 3)).size(), 2u);
}

TEST(RunTracker, ALostControllerAbortsTheRun) {
  RunTracker t = tracker();
  feed(t, {at(Interp::Running, 4)});
  const auto events = t.lost("connection closed");
  ASSERT_EQ(events.size(), 1u);
  EXPECT_TRUE(events[0].aborted);
  EXPECT_TRUE(t.lost("again").empty());
}

TEST(RunTracker, LoopsAreFollowedPassByPass) {
  const std::string program = "G21\n#1=0\no1 while [#1 LT 3]\nG1 X[#1] F100\nG1 Y[#1]\n#1=[#1+1]\no1 endwhile\nM2\n";
  RunTracker t([&](const std::string&) {
    RunProgram p;
    p.text = program;
    p.order = execution_order("l.ngc", program, {});
    return p;
  });
  // second pass seen on line 5, then the third pass on line 4
  auto events = feed(t, {at(Interp::Running, 4), at(Interp::Running, 5), at(Interp::Running, 4),
                         at(Interp::Running, 5), at(Interp::Running, 4)});
  EXPECT_EQ(block_lines(events), (std::vector<std::uint32_t>{1, 2, 4, 5, 6, 4, 5, 6, 4}));
}
