// Arcs stay arcs (TRIMMED_CURVE on a CIRCLE), helices become polylines within the tolerance.
#include <gtest/gtest.h>

#include <cmath>

#include "canonical_stream.hpp"
#include "test_support.hpp"

namespace ncbridge::cc1_builder::testing {
namespace {

using stepnc::CartesianPoint;
using stepnc::TrimmedCircle;

const stepnc::CompositeCurve& cut_curve(const stepnc::Project& p) {
  return stepnc::machining_operation(operation_of(p, 0)).its_toolpath->its_list.at(0).basiccurve;
}

CanonicalStream start_at(double x, double y, double z) {
  CanonicalStream s;
  s.tool(1).spindle_cw(1000).feed(500).rapid(x, y, z);
  return s;
}

TEST(Arcs, CounterClockwiseQuarterArcIsOneTrimmedCircle) {
  auto s = start_at(10, 0, -1);
  s.line(20, 0, -1).arc(30, 10, -1, 20, 10, 1).line(30, 20, -1).end();
  const auto p = build_cc1(s.calls, paper_options());
  const auto& c = cut_curve(p);
  ASSERT_EQ(c.segments.size(), 3u);  // polyline, arc, polyline
  const auto& arc = std::get<TrimmedCircle>(c.segments[1]);
  EXPECT_EQ(arc.position.location, (CartesianPoint{20, 10, -1}));
  EXPECT_EQ(arc.position.axis, (stepnc::Direction{0, 0, 1}));
  EXPECT_DOUBLE_EQ(arc.radius, 10);
  EXPECT_TRUE(arc.sense_agreement);
  EXPECT_EQ(arc.trim_1_point, (CartesianPoint{20, 0, -1}));
  EXPECT_EQ(arc.trim_2_point, (CartesianPoint{30, 10, -1}));
  EXPECT_DOUBLE_EQ(arc.trim_1_parameter, 0);
  EXPECT_NEAR(arc.trim_2_parameter, 90, 1e-9);
  EXPECT_NEAR(stepnc::sweep_degrees(arc), 90, 1e-9);
  EXPECT_EQ(std::get<stepnc::Polyline>(c.segments[2]).points.front(), (CartesianPoint{30, 10, -1}));
}

TEST(Arcs, ClockwiseArcRunsAgainstTheCircleParameter) {
  auto s = start_at(0, 10, 0);
  s.arc(10, 0, 0, 0, 0, -1).end();  // G2 from 12 o'clock to 3 o'clock about the origin
  const auto p = build_cc1(s.calls, paper_options());
  const auto& arc = std::get<TrimmedCircle>(cut_curve(p).segments.at(0));
  EXPECT_FALSE(arc.sense_agreement);
  EXPECT_NEAR(stepnc::sweep_degrees(arc), 90, 1e-9);
  EXPECT_NEAR(arc.trim_2_parameter, 270, 1e-9);
  EXPECT_NEAR(arc.position.ref_direction.y, 1, 1e-12);  // parameter 0 points at the start
}

TEST(Arcs, FullCircleIsSplitIntoTwoHalves) {
  auto s = start_at(10, 0, -2);
  s.arc(10, 0, -2, 0, 0, 1).end();
  const auto p = build_cc1(s.calls, paper_options());
  const auto& c = cut_curve(p);
  ASSERT_EQ(c.segments.size(), 2u);
  const auto& first = std::get<TrimmedCircle>(c.segments[0]);
  const auto& second = std::get<TrimmedCircle>(c.segments[1]);
  EXPECT_NEAR(first.trim_2_point.x, -10, 1e-9);
  EXPECT_NEAR(first.trim_2_point.y, 0, 1e-9);
  EXPECT_EQ(second.trim_1_point, first.trim_2_point);
  EXPECT_EQ(second.trim_2_point, (CartesianPoint{10, 0, -2}));
  EXPECT_NEAR(stepnc::sweep_degrees(first) + stepnc::sweep_degrees(second), 360, 1e-9);
}

TEST(Arcs, HelixIsAPolylineOnTheCylinderWithinTheTolerance) {
  auto s = start_at(5, 0, 0);
  s.arc(5, 0, -3, 0, 0, 1).end();  // one turn down 3 mm, radius 5
  Options o = paper_options();
  o.helix_chord_tolerance = 0.01;
  const auto p = build_cc1(s.calls, o);
  const auto& c = cut_curve(p);
  ASSERT_EQ(c.segments.size(), 1u);
  const auto& pts = std::get<stepnc::Polyline>(c.segments[0]).points;
  ASSERT_GT(pts.size(), 10u);
  EXPECT_EQ(pts.front(), (CartesianPoint{5, 0, 0}));
  EXPECT_EQ(pts.back(), (CartesianPoint{5, 0, -3}));
  double previous_z = 1;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    EXPECT_NEAR(std::hypot(pts[i].x, pts[i].y), 5, 1e-9);
    EXPECT_LT(pts[i].z, previous_z);  // descends steadily
    previous_z = pts[i].z;
    // Chord sagitta within tolerance: midpoint of the chord stays within 0.01 of the circle.
    const double mx = (pts[i].x + pts[i + 1].x) / 2, my = (pts[i].y + pts[i + 1].y) / 2;
    EXPECT_LE(5 - std::hypot(mx, my), 0.01 + 1e-12);
  }
}

TEST(Arcs, ArcInXzPlaneTurnsAboutY) {
  auto s = start_at(10, 0, 0);
  s.add(canonical::SelectPlane{canonical::Plane::XZ});
  // G18 arc: first axis Z, second axis X; from (x10,z0) to (x0,z-10) about (x0,z0), a quarter
  // turn counter-clockwise about +Y.
  s.add(canonical::ArcFeed{-10, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0});
  s.end();
  const auto p = build_cc1(s.calls, paper_options());
  const auto& op = stepnc::machining_operation(operation_of(p, 0));
  const auto& arc = std::get<TrimmedCircle>(op.its_toolpath->its_list[0].basiccurve.segments.at(0));
  EXPECT_EQ(arc.position.axis, (stepnc::Direction{0, 1, 0}));
  EXPECT_EQ(arc.trim_2_point, (CartesianPoint{0, 0, -10}));
  EXPECT_NEAR(stepnc::sweep_degrees(arc), 90, 1e-9);
  // The depth plane of its toolpath feature is the arc's lowest point.
  const auto& feature = std::get<stepnc::ToolpathFeature>(p.feature(workingstep(p, 0).its_feature));
  EXPECT_NEAR(feature.depth.position.location.z, -10, 1e-9);
}

}  // namespace
}  // namespace ncbridge::cc1_builder::testing
