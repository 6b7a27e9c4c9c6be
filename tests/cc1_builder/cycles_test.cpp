// Canned cycles -> drilling-family operations on ROUND_HOLE features (docs/cc1.md, "Canned cycles").
#include <gtest/gtest.h>

#include "canonical_stream.hpp"
#include "test_support.hpp"

namespace ncbridge::cc1_builder::testing {
namespace {

using stepnc::CartesianPoint;

const stepnc::RoundHole& hole_of(const stepnc::Project& p, std::size_t nth_ws) {
  return std::get<stepnc::RoundHole>(p.feature(workingstep(p, nth_ws).its_feature));
}

TEST(Cycles, G81IsDrillingOnARoundHoleAtTheHolePosition) {
  CanonicalStream s;
  s.tool(2).spindle_cw(800).feed(900).rapid(20, 60, 30);
  s.drill_hole(810, 20, 60, 10, -18, 30).end();
  const auto p = build_cc1(s.calls, paper_options());
  EXPECT_EQ(workplan_shape(p), "W");
  const auto& op = std::get<stepnc::Drilling>(operation_of(p, 0));
  const auto& hole = hole_of(p, 0);
  // Stock top Z5: the hole starts there and goes 23 mm down; the R plane is 5 mm above it.
  EXPECT_EQ(hole.feature_placement.location, (CartesianPoint{20, 60, 5}));
  EXPECT_EQ(hole.depth.position.location, (CartesianPoint{0, 0, -23}));
  EXPECT_EQ(hole.diameter.theoretical_size, 20);  // the drill's diameter
  EXPECT_EQ(std::get<stepnc::ConicalHoleBottom>(hole.bottom_condition).tip_angle, 118);
  EXPECT_EQ(op.cutting_depth, 23.0);
  EXPECT_EQ(op.retract_plane, 5.0);
  EXPECT_FALSE(op.dwell_time_bottom);
  EXPECT_EQ(p.tool(op.its_tool).body, stepnc::ToolBody::TwistDrill);
  EXPECT_DOUBLE_EQ(*p.technology(op.its_technology).feedrate, 0.015);
}

TEST(Cycles, EachHoleOfASeriesIsItsOwnWorkingstep) {
  CanonicalStream s;
  s.tool(2).spindle_cw(800).feed(900).rapid(0, 0, 30);
  s.drill_hole(810, 20, 60, 10, -18, 30).drill_hole(810, 40, 60, 10, -18, 30).drill_hole(820, 60, 60, 10, -18, 30, 0, 0.5);
  s.rapid(60, 60, 50).end();
  const auto p = build_cc1(s.calls, paper_options());
  EXPECT_EQ(workplan_shape(p), "WWWR");
  EXPECT_EQ(hole_of(p, 1).feature_placement.location.x, 40);
  EXPECT_EQ(std::get<stepnc::Drilling>(operation_of(p, 2)).dwell_time_bottom, 0.5);
}

TEST(Cycles, PeckDrillingIsMultistepWithStepAndMeasuredRetract) {
  CanonicalStream s;
  s.tool(2).spindle_cw(800).feed(900).rapid(20, 60, 30);
  s.drill_hole(730, 20, 60, 10, -20, 30, 8).end();
  const auto p = build_cc1(s.calls, paper_options());
  const auto& op = std::get<stepnc::MultistepDrilling>(operation_of(p, 0));
  EXPECT_EQ(op.first_depth, 8);
  EXPECT_EQ(op.depth_of_step, 8);
  EXPECT_NEAR(op.retract_distance, 0.254, 1e-12);  // G73: chip-breaking retract
  EXPECT_EQ(op.cutting_depth, 25.0);
}

TEST(Cycles, G85WithAReamerIsReamingWithFeedOut) {
  CanonicalStream s;
  s.tool(3).spindle_cw(300).feed(300).rapid(20, 60, 30);
  s.drill_hole(850, 20, 60, 10, -60, 30).end();
  const auto p = build_cc1(s.calls, paper_options());
  const auto& op = std::get<stepnc::Reaming>(operation_of(p, 0));
  EXPECT_FALSE(op.spindle_stop_at_bottom);
  EXPECT_EQ(op.feed_on_retract, 1.0);
  EXPECT_EQ(hole_of(p, 0).diameter.theoretical_size, 22);
  EXPECT_TRUE(std::holds_alternative<stepnc::ThroughBottomCondition>(hole_of(p, 0).bottom_condition))
      << "Z-60 is below the stock bottom Z-50";
}

TEST(Cycles, HoleThenMillingAreSeparateWorkingsteps) {
  CanonicalStream s;
  s.tool(2).spindle_cw(800).feed(900).rapid(20, 60, 30);
  s.drill_hole(810, 20, 60, 10, -18, 30);
  s.rapid(20, 60, 30).tool(1).spindle_cw(1000).feed(300).rapid(0, 0, 5).line(0, 0, -1).end();
  const auto p = build_cc1(s.calls, paper_options());
  EXPECT_EQ(workplan_shape(p), "WRRW");
  EXPECT_TRUE(std::holds_alternative<stepnc::RoundHole>(p.feature(workingstep(p, 0).its_feature)));
  EXPECT_TRUE(std::holds_alternative<stepnc::ToolpathFeature>(p.feature(workingstep(p, 1).its_feature)));
}

}  // namespace
}  // namespace ncbridge::cc1_builder::testing
