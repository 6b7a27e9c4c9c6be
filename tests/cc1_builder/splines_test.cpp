// NURBS_FEED (G5, G5.1, G5.2/G5.3) in CC1: a B-spline segment with LinuxCNC's knots, evaluated
// and followed as chords as the recogniser and the report do.
#include <gtest/gtest.h>

#include <cmath>

#include "canonical_stream.hpp"
#include "test_support.hpp"
#include "toolpath_curve.hpp"

namespace ncbridge::cc1_builder::testing {
namespace {

using stepnc::BSplineCurve;
using stepnc::CartesianPoint;

TEST(Splines, LinuxCncKnotsAreClampedUniform) {
  const std::vector<CartesianPoint> points{{0, 0, 1}, {1, 1, 1}, {2, 0, 1}, {3, 1, 1}, {4, 0, 1}, {5, 1, 1}};
  const BSplineCurve c = nurbs_curve(points, std::vector<double>(6, 1.0), 4);
  EXPECT_EQ(c.degree, 3);
  EXPECT_EQ(c.knots, (std::vector<double>{0, 1, 2, 3}));  // 0 0 0 0 1 2 3 3 3 3
  EXPECT_EQ(c.knot_multiplicities, (std::vector<int>{4, 1, 1, 4}));
  EXPECT_EQ(c.knot_spec, stepnc::KnotType::QuasiUniformKnots);
  EXPECT_TRUE(c.weights.empty());  // equal weights: not rational
  EXPECT_EQ(stepnc::bspline_point(c, 0), points.front());
  EXPECT_EQ(stepnc::bspline_point(c, 3), points.back());
  EXPECT_THROW(nurbs_curve(points, std::vector<double>(6, 1.0), 7), std::invalid_argument);  // order > points
  EXPECT_THROW(nurbs_curve(points, {1, 1, 0, 1, 1, 1}, 3), std::invalid_argument);            // a zero weight
}

TEST(Splines, ARationalQuarterCircleIsFollowedWithinTheTolerance) {
  // The exact quarter of the unit circle: weights 1, sqrt(2)/2, 1.
  const BSplineCurve c = nurbs_curve({{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, std::sqrt(0.5), 1}, 3);
  ASSERT_EQ(c.weights.size(), 3u);
  for (double u = 0; u <= 1.0; u += 0.125) {
    const CartesianPoint p = stepnc::bspline_point(c, u);
    EXPECT_NEAR(std::hypot(p.x, p.y), 1.0, 1e-12) << u;
  }
  const double tolerance = 1e-4;
  const auto points = stepnc::bspline_polyline(c, tolerance);
  ASSERT_GE(points.size(), 3u);
  EXPECT_EQ(points.front(), (CartesianPoint{1, 0, 0}));
  EXPECT_EQ(points.back(), (CartesianPoint{0, 1, 0}));
  // A chord of a unit circle strays from it by its sagitta, 1 - cos(half the angle it spans).
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double half = std::acos(points[i - 1].x * points[i].x + points[i - 1].y * points[i].y) / 2;
    EXPECT_LE(1 - std::cos(half), tolerance * 1.0001) << i;
  }
  EXPECT_LT(points.size(), 80u);  // and not far more points than needed (about 56 at 1e-4)
}

TEST(Splines, ANurbsFeedIsOneSegmentOfTheCutAtItsHeight) {
  CanonicalStream s;
  s.tool(1).spindle_cw(1000).feed(300).rapid(0, 0, 5).line(0, 0, -2);
  s.add(canonical::NurbsFeed{{{0, 0, 1}, {10, 0, 1}, {10, 10, 1}, {20, 10, 1}}, 4});
  s.line(30, 10, -2).end();
  const auto p = build_cc1(s.calls, paper_options());
  const auto& curve = stepnc::machining_operation(operation_of(p, 0)).its_toolpath->its_list.at(0).basiccurve;
  ASSERT_EQ(curve.segments.size(), 3u);  // line, spline, line
  const auto& spline = std::get<BSplineCurve>(curve.segments[1]);
  EXPECT_EQ(spline.control_points.front(), (CartesianPoint{0, 0, -2}));
  EXPECT_EQ(spline.control_points.back(), (CartesianPoint{20, 10, -2}));
  EXPECT_EQ(spline.knot_spec, stepnc::KnotType::PiecewiseBezierKnots);
  EXPECT_EQ(std::get<stepnc::Polyline>(curve.segments[2]).points.front(), (CartesianPoint{20, 10, -2}));
}

}  // namespace
}  // namespace ncbridge::cc1_builder::testing
