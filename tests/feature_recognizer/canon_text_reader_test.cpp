// The test-side reader of rs274's canonical text and the workingstep segmenter.
#include <gtest/gtest.h>

#include "canon_text_reader.hpp"
#include "ncbridge/common/error.hpp"
#include "toolpath_segmenter.hpp"

namespace fr = ncbridge::feature_recognizer;
using ncbridge::test_support::parse_canon_text;
using ncbridge::test_support::segment_workingsteps;

namespace {

ncbridge::setup::ToolList tools() {
  ncbridge::setup::Tool t1;
  t1.number = 1, t1.type = ncbridge::setup::ToolType::FlatEndMill, t1.diameter = 10;
  ncbridge::setup::Tool t2;
  t2.number = 2, t2.type = ncbridge::setup::ToolType::Drill, t2.diameter = 6;
  return ncbridge::setup::ToolList({t1, t2});
}

constexpr const char* kProgram =
    "    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)\n"
    "    2 N..... COMMENT(\"F3_Pocket\")\n"
    "    3 N..... SELECT_TOOL(1)\n"
    "    4 N..... CHANGE_TOOL(1)\n"
    "    5 N..... SET_SPINDLE_SPEED(0, 8000.0000)\n"
    "    6 N..... STRAIGHT_TRAVERSE(10.0000, 10.0000, 5.0000, 0.0000, 0.0000, 0.0000)\n"
    "    7 N..... SET_FEED_RATE(250.0000)\n"
    "    8 N..... STRAIGHT_FEED(10.0000, 10.0000, -2.0000, 0.0000, 0.0000, 0.0000)\n"
    "    9 N..... SET_FEED_RATE(900.0000)\n"
    "   10 N..... ARC_FEED(20.0000, 20.0000, 20.0000, 10.0000, -1, -2.0000, 0.0000, 0.0000, 0.0000)\n"
    "   11 N..... STRAIGHT_TRAVERSE(20.0000, 20.0000, 5.0000, 0.0000, 0.0000, 0.0000)\n"
    "   12 N..... STRAIGHT_TRAVERSE(40.0000, 20.0000, 5.0000, 0.0000, 0.0000, 0.0000)\n"
    "   13 N..... STRAIGHT_FEED(40.0000, 20.0000, -2.0000, 0.0000, 0.0000, 0.0000)\n"
    "   14 N..... CHANGE_TOOL(2)\n"
    "   15 N..... STRAIGHT_FEED(40.0000, 20.0000, -8.0000, 0.0000, 0.0000, 0.0000)\n"
    "   16 N..... PROGRAM_END()\n";

}  // namespace

TEST(CanonTextReader, DecodesMotionAndSkipsComments) {
  const auto calls = parse_canon_text(kProgram, "p.canon");
  ASSERT_EQ(calls.size(), 15u);  // the comment is skipped
  const auto* arc = std::get_if<ncbridge::canonical::ArcFeed>(&calls[8].data);
  ASSERT_NE(arc, nullptr);
  EXPECT_DOUBLE_EQ(arc->first_end, 20);
  EXPECT_DOUBLE_EQ(arc->second_axis, 10);
  EXPECT_EQ(arc->rotation, -1);
  EXPECT_DOUBLE_EQ(arc->axis_end_point, -2);
  EXPECT_EQ(calls[8].source.line, 10u);
}

TEST(CanonTextReader, BadNumberNamesLineAndColumn) {
  try {
    parse_canon_text("    1 N..... STRAIGHT_FEED(1.0, x2, 3.0, 0, 0, 0)\n", "bad.canon");
    FAIL() << "expected InputError";
  } catch (const ncbridge::InputError& e) {
    EXPECT_EQ(e.where().file, "bad.canon");
    EXPECT_EQ(e.where().line, 1u);
    EXPECT_GT(e.where().column, 0u);
  }
  EXPECT_THROW(parse_canon_text("garbage\n", "bad.canon"), ncbridge::InputError);
  EXPECT_THROW(parse_canon_text("    1 N..... STRAIGHT_FEED(1.0)\n", "bad.canon"), ncbridge::InputError);
}

TEST(ToolpathSegmenter, SplitsAtRetractsAndToolChanges) {
  const auto ws = segment_workingsteps(parse_canon_text(kProgram, "p.canon"), tools());
  ASSERT_EQ(ws.size(), 3u);
  EXPECT_EQ(ws[0].tool.number, 1);
  EXPECT_DOUBLE_EQ(ws[0].tool.diameter, 10);
  EXPECT_DOUBLE_EQ(ws[0].spindle_rpm, 8000);
  EXPECT_DOUBLE_EQ(ws[0].feed, 900);
  ASSERT_EQ(ws[0].moves.size(), 3u);  // rapid, plunge, arc
  EXPECT_EQ(ws[0].moves[2].kind, fr::MoveKind::Arc);
  EXPECT_TRUE(ws[0].moves[2].clockwise);
  EXPECT_DOUBLE_EQ(ws[0].moves[2].center_x, 20);
  // The retract starts a new workingstep, whose rapids lead to its first cut.
  EXPECT_EQ(ws[1].moves.front().kind, fr::MoveKind::Rapid);
  EXPECT_EQ(ws[1].tool.number, 1);
  EXPECT_EQ(ws[2].tool.number, 2);
  EXPECT_EQ(ws[2].tool.type, ncbridge::setup::ToolType::Drill);
}

TEST(ToolpathSegmenter, InchProgramsBecomeMillimetres) {
  const auto calls = parse_canon_text(
      "    1 N..... USE_LENGTH_UNITS(CANON_UNITS_INCHES)\n"
      "    2 N..... CHANGE_TOOL(1)\n"
      "    3 N..... STRAIGHT_FEED(1.0000, 2.0000, -0.5000, 0.0000, 0.0000, 0.0000)\n",
      "inch.canon");
  const auto ws = segment_workingsteps(calls, tools());
  ASSERT_EQ(ws.size(), 1u);
  EXPECT_DOUBLE_EQ(ws[0].moves[0].end.x, 25.4);
  EXPECT_DOUBLE_EQ(ws[0].moves[0].end.z, -12.7);
}
