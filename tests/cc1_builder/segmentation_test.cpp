// Workingstep segmentation on hand-made canonical streams (docs/cc1.md, "Segmentation").
#include <gtest/gtest.h>

#include "canonical_stream.hpp"
#include "test_support.hpp"

namespace ncbridge::cc1_builder::testing {
namespace {

using stepnc::CartesianPoint;

// The paper's Table 2 stream: one face-milling layer.
CanonicalStream face_mill_stream() {
  CanonicalStream s;
  s.tool(1).flood(true).spindle_cw(720).rapid(91.9, -13.5, 100).rapid(91.9, -13.5, 15).feed(240);
  s.line(91.9, -13.5, 0).line(91.9, 133.5, 0).line(74.8, 133.5, 0).line(74.8, -13.5, 0);
  s.line(57.7, -13.5, 0).line(57.7, 133.5, 0).line(40.6, 133.5, 0).line(40.6, -13.5, 0);
  s.line(23.5, -13.5, 0).line(23.5, 133.5, 0).line(6.4, 133.5, 0).line(6.4, -13.5, 0);
  s.rapid(6.4, -13.5, 15).end();
  return s;
}

TEST(Segmentation, FaceMillIsApproachWorkingstepAndRetract) {
  const auto p = build_cc1(face_mill_stream().calls, paper_options());
  EXPECT_EQ(workplan_shape(p), "RWR");
  const auto pts = polyline_points(operation_of(p, 0));
  ASSERT_EQ(pts.size(), 13u);  // the paper's 13 cutter-location points
  EXPECT_EQ(pts.front(), (CartesianPoint{91.9, -13.5, 15}));
  EXPECT_EQ(pts[1], (CartesianPoint{91.9, -13.5, 0}));
  EXPECT_EQ(pts.back(), (CartesianPoint{6.4, -13.5, 0}));
  const auto& after = rapid_movement(p, 1);
  const auto& retract = std::get<stepnc::Polyline>(after.its_toolpath->its_list.at(0).basiccurve.segments.at(0));
  EXPECT_EQ(retract.points, (std::vector<CartesianPoint>{{6.4, -13.5, 0}, {6.4, -13.5, 15}}));
  // The operation retracts to Z15; the security plane is the highest rapid level.
  EXPECT_EQ(stepnc::machining_operation(operation_of(p, 0)).retract_plane, 15.0);
  EXPECT_EQ(workingstep(p, 0).its_secplane.position.location.z, 100.0);
  EXPECT_EQ(p.setup.its_secplane.position.location.z, 100.0);
  // The toolpath feature's depth plane is at the lowest cut.
  const auto& feature = std::get<stepnc::ToolpathFeature>(p.feature(workingstep(p, 0).its_feature));
  EXPECT_EQ(feature.depth.position.location.z, 0.0);
  EXPECT_EQ(workingstep(p, 0).source.first_line, 9u);  // the first STRAIGHT_FEED
}

TEST(Segmentation, RetractBetweenCutsStartsANewWorkingstep) {
  CanonicalStream s;
  s.tool(1).spindle_cw(1000).feed(300).rapid(0, 0, 5);
  s.line(0, 0, -1).line(10, 0, -1).rapid(10, 0, 5).rapid(20, 0, 5).rapid(20, 0, 1);
  s.line(20, 0, -1).line(30, 0, -1).end();
  const auto p = build_cc1(s.calls, paper_options());
  EXPECT_EQ(workplan_shape(p), "WRW");
  EXPECT_EQ(rapid_movement(p, 0).its_toolpath->its_list[0].its_type, stepnc::ToolpathType::Connect);
  EXPECT_EQ(std::get<stepnc::Polyline>(rapid_movement(p, 0).its_toolpath->its_list[0].basiccurve.segments[0]).points.size(), 4u);
}

TEST(Segmentation, LinkThatStaysDownIsAConnectTrajectoryInsideTheOperation) {
  CanonicalStream s;
  s.tool(1).spindle_cw(1000).feed(300).rapid(0, 0, 5);
  s.line(0, 0, -1).line(10, 0, -1).rapid(10, 5, -1).line(0, 5, -1).end();
  const auto p = build_cc1(s.calls, paper_options());
  EXPECT_EQ(workplan_shape(p), "W");
  const auto& list = stepnc::machining_operation(operation_of(p, 0)).its_toolpath->its_list;
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0].its_type, stepnc::ToolpathType::TrajectoryPath);
  EXPECT_EQ(list[1].its_type, stepnc::ToolpathType::Connect);
  EXPECT_EQ(list[2].its_type, stepnc::ToolpathType::TrajectoryPath);
}

TEST(Segmentation, ToolChangeStartsANewWorkingstepWithThatTool) {
  CanonicalStream s;
  s.tool(1).spindle_cw(1000).feed(300).rapid(0, 0, 5).line(0, 0, -1).line(5, 0, -1);
  s.tool(3).spindle_cw(1000).feed(300).line(5, 5, -1).end();
  const auto p = build_cc1(s.calls, paper_options());
  EXPECT_EQ(workplan_shape(p), "WW");
  EXPECT_EQ(p.tool(stepnc::machining_operation(operation_of(p, 0)).its_tool).number, 1);
  EXPECT_EQ(p.tool(stepnc::machining_operation(operation_of(p, 1)).its_tool).number, 3);
  EXPECT_EQ(p.tools.size(), 2u);
}

TEST(Segmentation, FeedChangeStartsANewWorkingstepThatContinuesTheToolpath) {
  CanonicalStream s;
  s.tool(1).spindle_cw(1200).rapid(70, 55, 2).feed(300).line(70, 55, -5.9);
  s.feed(2400).line(70, 90, -5.9).line(75, 90, -5.9).end();
  const auto p = build_cc1(s.calls, paper_options());
  EXPECT_EQ(workplan_shape(p), "WW");  // one rapid from an unknown position draws nothing
  const auto second = polyline_points(operation_of(p, 1));
  EXPECT_EQ(second.front(), (CartesianPoint{70, 55, -5.9}));  // starts where the plunge ended
  EXPECT_EQ(p.technologies.size(), 2u);
  EXPECT_DOUBLE_EQ(*p.technology(stepnc::machining_operation(operation_of(p, 1)).its_technology).feedrate, 0.04);
}

TEST(Segmentation, SpindleDirectionAndCoolantChangesStartNewWorkingsteps) {
  CanonicalStream s;
  s.tool(1).spindle_cw(600).feed(100).rapid(0, 0, 1).line(1, 0, 0);
  s.spindle_ccw(600).line(2, 0, 0);
  s.flood(true).line(3, 0, 0);
  s.line(4, 0, 0).end();
  const auto p = build_cc1(s.calls, paper_options());
  EXPECT_EQ(workplan_shape(p), "WWW");
  EXPECT_EQ(p.machine_functions.size(), 2u);
  EXPECT_TRUE(p.functions(stepnc::machining_operation(operation_of(p, 2)).its_machine_functions).coolant);
}

TEST(Segmentation, SameTechnologyIsSharedNotDuplicated) {
  CanonicalStream s;
  s.tool(1).spindle_cw(600).feed(100).rapid(0, 0, 5).line(0, 0, 0).rapid(0, 0, 5).rapid(5, 0, 5).line(5, 0, 0).end();
  const auto p = build_cc1(s.calls, paper_options());
  EXPECT_EQ(workplan_shape(p), "WRW");
  EXPECT_EQ(p.technologies.size(), 1u);
  EXPECT_EQ(p.machine_functions.size(), 1u);
}

TEST(Segmentation, CuttingWithAToolNotInTheListIsAnErrorAtItsLine) {
  CanonicalStream s;
  s.tool(7).spindle_cw(600).feed(100).rapid(0, 0, 5).line(0, 0, 0);
  Cc1Builder b(paper_options());
  b.source_file(0, "part.ngc");
  try {
    for (const auto& c : s.calls) b.call(c);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "part.ngc");
    EXPECT_EQ(e.where().line, s.current_line());
    EXPECT_NE(std::string(e.what()).find("T7"), std::string::npos);
  }
}

TEST(Segmentation, FirstMotionAsFeedWarnsAndStartsThere) {
  CanonicalStream s;
  s.tool(1).spindle_cw(600).feed(100).line(0, 0, 0).line(5, 0, 0).end();
  std::vector<Warning> warnings;
  const auto p = build_cc1(s.calls, paper_options(), &warnings);
  EXPECT_EQ(workplan_shape(p), "W");
  EXPECT_EQ(polyline_points(operation_of(p, 0)), (std::vector<CartesianPoint>{{0, 0, 0}, {5, 0, 0}}));
  ASSERT_EQ(warnings.size(), 1u);
}

TEST(Segmentation, RepeatedProbeWarningsAreSummedUpAfterTen) {
  CanonicalStream s;
  s.tool(1).spindle_cw(600).feed(100).rapid(0, 0, 5);
  canonical::Pose away;
  away.z = 10;
  for (int i = 0; i < 25; ++i) s.add(canonical::StraightProbe{away, 2});  // G38.4: away from contact
  s.end();
  std::vector<Warning> warnings;
  const auto p = build_cc1(s.calls, paper_options(), &warnings);
  EXPECT_EQ(workplan_shape(p), "");  // nothing but the probes, left out
  ASSERT_EQ(warnings.size(), 11u);
  EXPECT_NE(warnings[0].message.find("probing away from the workpiece (G38.4, G38.5)"), std::string::npos);
  EXPECT_EQ(warnings[10].message.rfind("15 more probing moves away", 0), 0u) << warnings[10].message;
  EXPECT_EQ(warnings[10].where.line, s.current_line() - 1);  // the last probe
}

// G38.2/G38.3 moves become WORKPIECE_PROBING workingsteps between the cuts, which still convert.
TEST(Segmentation, ProbingTowardsThePartIsAWorkpieceProbing) {
  CanonicalStream s;
  canonical::Pose down;
  down.x = 10;
  down.y = 20;
  down.z = -15;
  canonical::Pose side = down;
  side.x = 40;
  s.tool(1).spindle_cw(600).feed(100).rapid(10, 20, 5);
  const std::uint32_t probe_line = s.current_line() + 1;
  s.add(canonical::StraightProbe{down, 0}).add(canonical::StraightProbe{side, 1});  // G38.2 Z, G38.3 X
  s.rapid(0, 0, 5).line(0, 0, -1).line(5, 0, -1).rapid(5, 0, 5).end();
  std::vector<Warning> warnings;
  const auto p = build_cc1(s.calls, paper_options(), &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front().message;
  ASSERT_EQ(workplan_shape(p), "PPRWR");  // a lone first traverse draws nothing
  const auto& z = std::get<stepnc::WorkpieceProbing>(p.main_workplan.its_elements[0]);
  EXPECT_EQ(z.start_position.location, (CartesianPoint{10, 20, 5}));
  EXPECT_EQ(z.its_direction, (stepnc::Direction{0, 0, -1}));
  EXPECT_DOUBLE_EQ(z.expected_value.theoretical_size, 10);  // contact anywhere in the 20 mm: 10 +/- 10
  EXPECT_DOUBLE_EQ(z.expected_value.upper_limit, 10);
  EXPECT_DOUBLE_EQ(z.expected_value.lower_limit, 10);
  EXPECT_EQ(z.measured_offset.its_name, "#5063");
  EXPECT_EQ(z.its_probe, "T1");
  EXPECT_EQ(z.source.first_line, probe_line);
  const auto& x = std::get<stepnc::WorkpieceProbing>(p.main_workplan.its_elements[1]);
  EXPECT_EQ(x.start_position.location, (CartesianPoint{10, 20, -15}));
  EXPECT_EQ(x.its_direction, (stepnc::Direction{1, 0, 0}));
  EXPECT_EQ(x.measured_offset.its_name, "#5061");
  EXPECT_EQ(polyline_points(operation_of(p, 0)), (std::vector<CartesianPoint>{{0, 0, 5}, {0, 0, -1}, {5, 0, -1}}));
}

TEST(Segmentation, WorkOffsetBecomesTheSetupOriginAndLaterChangesAreConverted) {
  CanonicalStream s;
  canonical::Pose g54;
  g54.x = 100;
  g54.y = 50;
  g54.z = -20;
  s.add(canonical::SetG5xOffset{1, g54});
  s.tool(1).spindle_cw(600).feed(100).rapid(0, 0, 5).line(0, 0, 0).line(5, 0, 0).rapid(5, 0, 5);
  canonical::Pose g55 = g54;
  g55.x = 200;
  s.add(canonical::SetG5xOffset{2, g55});
  s.rapid(0, 0, 5).line(0, 0, 0).end();
  std::vector<Warning> warnings;
  const auto p = build_cc1(s.calls, paper_options(), &warnings);
  ASSERT_TRUE(p.setup.its_origin);
  EXPECT_EQ(p.setup.its_origin->location, (CartesianPoint{100, 50, -20}));
  EXPECT_EQ(polyline_points(operation_of(p, 1)).back(), (CartesianPoint{100, 0, 0}));
  EXPECT_EQ(warnings.size(), 1u);
}

}  // namespace
}  // namespace ncbridge::cc1_builder::testing

namespace ncbridge::cc1_builder::testing {
namespace {

TEST(Segmentation, FeedsThatDoNotMoveMakeNoWorkingstep) {
  CanonicalStream s;
  s.tool(1).spindle_cw(600).feed(100).rapid(0, 0, 5).rapid(0, 0, 0).line(0, 0, 0).rapid(0, 0, 5).end();
  const auto p = build_cc1(s.calls, paper_options());
  EXPECT_EQ(workplan_shape(p), "RR");
  EXPECT_TRUE(p.operations.empty());
}

}  // namespace
}  // namespace ncbridge::cc1_builder::testing
