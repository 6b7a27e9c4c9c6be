// MILLING_TECHNOLOGY units (feed m/s, spindle rev/s, negative = clockwise), tools, units.
#include <gtest/gtest.h>

#include "canonical_stream.hpp"
#include "test_support.hpp"

namespace ncbridge::cc1_builder::testing {
namespace {

TEST(Technology, FeedInMetresPerSecondAndClockwiseSpindleNegative) {
  CanonicalStream s;
  s.tool(1).spindle_cw(720).feed(240).rapid(0, 0, 5).line(0, 0, 0).end();
  const auto p = build_cc1(s.calls, paper_options());
  const auto& t = p.technology(stepnc::machining_operation(operation_of(p, 0)).its_technology);
  EXPECT_DOUBLE_EQ(*t.feedrate, 0.004);  // 240 mm/min
  EXPECT_DOUBLE_EQ(*t.spindle, -12.0);   // 720 rpm clockwise (M3)
  EXPECT_FALSE(t.cutspeed);
  EXPECT_FALSE(t.feedrate_per_tooth);
  EXPECT_EQ(t.feedrate_reference, stepnc::ToolReferencePoint::Tcp);
}

TEST(Technology, CounterClockwiseSpindlePositive) {
  CanonicalStream s;
  s.tool(1).spindle_ccw(960).feed(1800).rapid(0, 0, 5).line(0, 0, 0).end();
  const auto p = build_cc1(s.calls, paper_options());
  const auto& t = p.technology(stepnc::machining_operation(operation_of(p, 0)).its_technology);
  EXPECT_DOUBLE_EQ(*t.spindle, 16.0);
  EXPECT_DOUBLE_EQ(*t.feedrate, 0.03);
}

TEST(Technology, InchProgramsBecomeMillimetres) {
  CanonicalStream s;
  s.inches().tool(1).spindle_cw(600).feed(10).rapid(1, 2, 0.5).line(1, 2, -0.25).end();
  const auto p = build_cc1(s.calls, paper_options());
  const auto& op = stepnc::machining_operation(operation_of(p, 0));
  EXPECT_DOUBLE_EQ(*p.technology(op.its_technology).feedrate, 10 * 25.4 / 60000);
  const auto pts = polyline_points(operation_of(p, 0));
  EXPECT_DOUBLE_EQ(pts.back().x, 25.4);
  EXPECT_DOUBLE_EQ(pts.back().y, 50.8);
  EXPECT_DOUBLE_EQ(pts.back().z, -6.35);
  EXPECT_DOUBLE_EQ(p.setup.its_secplane.position.location.z, 12.7);
}

TEST(Technology, ToolsMapToTheirIso14649Bodies) {
  CanonicalStream s;
  s.tool(1).spindle_cw(600).feed(100).rapid(0, 0, 5).line(0, 0, 0).end();
  const auto p = build_cc1(s.calls, paper_options());
  ASSERT_EQ(p.tools.size(), 1u);
  const auto& t = p.tools[0];
  EXPECT_EQ(t.its_id, "T1 ENDMILL_18MM");
  EXPECT_EQ(t.body, stepnc::ToolBody::Endmill);
  EXPECT_EQ(t.dimension.diameter, 18);
  EXPECT_EQ(t.number_of_teeth, 4);
  EXPECT_EQ(t.tool_offset_length, 50);
}

TEST(Technology, StockBecomesTheRawpieceBlock) {
  CanonicalStream s;
  s.tool(1).spindle_cw(600).feed(100).rapid(0, 0, 5).line(0, 0, 0).end();
  const auto p = build_cc1(s.calls, paper_options());
  ASSERT_TRUE(p.rawpiece);
  ASSERT_TRUE(p.rawpiece->its_bounding_geometry);
  EXPECT_EQ(p.rawpiece->its_bounding_geometry->position.location, (stepnc::CartesianPoint{0, 0, -50}));
  EXPECT_EQ(p.rawpiece->its_bounding_geometry->x, 100);
  EXPECT_EQ(p.rawpiece->its_bounding_geometry->y, 120);
  EXPECT_EQ(p.rawpiece->its_bounding_geometry->z, 55);
}

}  // namespace
}  // namespace ncbridge::cc1_builder::testing
