#include <gtest/gtest.h>

#include "ncbridge/capture/mtconnect_run.hpp"
#include "ncbridge/capture/mtconnect_streams.hpp"
#include "ncbridge/common/error.hpp"

using namespace ncbridge::capture;

namespace {

// An answer shaped as MTConnect Part 3 shows it (namespaces, components, Events/Samples).
std::string streams(std::uint64_t instance, std::uint64_t first, std::uint64_t next, const std::string& events) {
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<MTConnectStreams xmlns:m="urn:mtconnect.org:MTConnectStreams:1.7" xmlns="urn:mtconnect.org:MTConnectStreams:1.7">
  <Header creationTime="2026-11-26T08:00:00Z" sender="agent" instanceId=")" +
         std::to_string(instance) + R"(" version="1.7.0" bufferSize="16" firstSequence=")" + std::to_string(first) +
         R"(" lastSequence=")" + std::to_string(next - 1) + R"(" nextSequence=")" + std::to_string(next) + R"("/>
  <Streams>
    <DeviceStream name="mill2" uuid="m2">
      <ComponentStream component="Path" name="path" componentId="p1">
        <Events>)" + events + R"(</Events>
        <Samples><PathPosition dataItemId="pp" timestamp="2026-11-26T08:00:00Z" sequence="3">0 0 5</PathPosition></Samples>
      </ComponentStream>
    </DeviceStream>
    <DeviceStream name="lathe1" uuid="l1">
      <ComponentStream component="Path" name="path" componentId="p2">
        <Events><Execution dataItemId="e2" timestamp="2026-11-26T08:00:00Z" sequence="4">ACTIVE</Execution></Events>
      </ComponentStream>
    </DeviceStream>
  </Streams>
</MTConnectStreams>)";
}

std::string event(const char* name, std::uint64_t seq, const char* value, const char* sub_type = nullptr) {
  std::string e = std::string("<") + name + " dataItemId=\"x\" timestamp=\"2026-11-26T08:00:00Z\" sequence=\"" +
                  std::to_string(seq) + "\"";
  if (sub_type) e += std::string(" subType=\"") + sub_type + "\"";
  return e + ">" + value + "</" + name + ">";
}

}  // namespace

TEST(MtconnectStreams, ReadsHeaderAndObservationsInSequenceOrder) {
  const auto s = parse_mtconnect_streams(streams(7, 1, 9,
                                                 event("Block", 8, "G1 X10") + event("Execution", 5, "ACTIVE") +
                                                     event("LineNumber", 6, "12", "ABSOLUTE") +
                                                     event("Program", 2, "part.ngc")));
  EXPECT_EQ(s.instance_id, 7u);
  EXPECT_EQ(s.first_sequence, 1u);
  EXPECT_EQ(s.next_sequence, 9u);
  ASSERT_EQ(s.observations.size(), 6u);
  for (std::size_t i = 1; i < s.observations.size(); ++i) EXPECT_LT(s.observations[i - 1].sequence, s.observations[i].sequence);
  EXPECT_EQ(s.observations[0].name, "Program");
  EXPECT_EQ(s.observations[0].device, "mill2");
  EXPECT_EQ(s.observations[4].sub_type, "ABSOLUTE");
}

TEST(MtconnectStreams, ErrorsAndOtherDocumentsAreInputErrors) {
  try {
    parse_mtconnect_streams(R"(<MTConnectError><Header instanceId="1"/><Errors><Error errorCode="OUT_OF_RANGE">'from' must be greater than 10</Error></Errors></MTConnectError>)");
    FAIL();
  } catch (const ncbridge::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("OUT_OF_RANGE"), std::string::npos);
  }
  EXPECT_THROW(parse_mtconnect_streams("<html/>"), ncbridge::InputError);
  EXPECT_THROW(parse_mtconnect_streams("<MTConnectStreams><Header instanceId=\"x\"/></MTConnectStreams>"), ncbridge::InputError);
  EXPECT_THROW(parse_mtconnect_streams("not xml <"), ncbridge::InputError);
}

TEST(MtconnectDevice, MapsExecutionProgramAndLinesToSamples) {
  MtconnectDevice d("mill2");
  const auto s = parse_mtconnect_streams(streams(1, 1, 20,
      event("ControllerMode", 1, "AUTOMATIC") + event("Program", 2, "/nc/p.ngc") + event("Execution", 5, "ACTIVE") +
      event("LineNumber", 6, "4", "ABSOLUTE") + event("LineNumber", 7, "9", "INCREMENTAL") +
      event("Execution", 8, "FEED_HOLD") + event("Execution", 9, "ACTIVE") + event("LineNumber", 10, "7") +
      event("Execution", 11, "PROGRAM_COMPLETED")));
  const auto samples = d.observe(s.observations);
  ASSERT_FALSE(samples.empty());
  EXPECT_EQ(samples.back().interp, ControllerSample::Interp::Idle);
  EXPECT_TRUE(samples.back().completed);
  EXPECT_EQ(samples.back().program, "/nc/p.ngc");
  EXPECT_EQ(samples.back().line, 7u);  // the INCREMENTAL line number is not a program line
  bool paused = false;
  for (const auto& x : samples) paused = paused || x.interp == ControllerSample::Interp::Paused;
  EXPECT_TRUE(paused);
  for (const auto& x : samples) EXPECT_NE(x.line, 9u);
}

TEST(SampleCursor, DropsWhatWasSeenAndTellsOfLostObservations) {
  SampleCursor c;
  auto a = c.accept(parse_mtconnect_streams(streams(1, 1, 10, event("Execution", 9, "READY"))));
  EXPECT_FALSE(a.lost);
  EXPECT_EQ(*c.next(), 10u);
  // an overlapping answer: 9 again, 10 and 11 new
  a = c.accept(parse_mtconnect_streams(streams(1, 1, 12, event("Execution", 9, "READY") + event("Execution", 10, "ACTIVE") +
                                                              event("LineNumber", 11, "3"))));
  EXPECT_FALSE(a.lost);
  EXPECT_EQ(a.fresh.size(), 2u);  // (the fixed PathPosition 3 and lathe 4 are old)
  // a retried, older answer never moves the cursor back
  c.accept(parse_mtconnect_streams(streams(1, 1, 11, event("Execution", 10, "ACTIVE"))));
  EXPECT_EQ(*c.next(), 12u);
  // the buffer moved past 12: lost
  a = c.accept(parse_mtconnect_streams(streams(1, 40, 50, event("LineNumber", 45, "9"))));
  EXPECT_TRUE(a.lost);
  EXPECT_NE(a.why.find("buffer"), std::string::npos);
  // the agent restarted: lost, sequences start again
  a = c.accept(parse_mtconnect_streams(streams(2, 1, 5, event("Execution", 3, "READY"))));
  EXPECT_TRUE(a.lost);
  EXPECT_NE(a.why.find("restarted"), std::string::npos);
  EXPECT_EQ(a.fresh.size(), 3u);  // everything of the new instance (both devices)
  EXPECT_EQ(*c.next(), 5u);
}
