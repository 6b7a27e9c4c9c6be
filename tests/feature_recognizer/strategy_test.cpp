// Milling strategy from the cutter-location path of one layer.
#include <gtest/gtest.h>

#include <cmath>

#include "cutting_layers.hpp"
#include "milling_strategy.hpp"
#include "swept_area.hpp"
#include "to_stepnc_strategy.hpp"
#include "toolpath_builder.hpp"

namespace fr = ncbridge::feature_recognizer;
using ncbridge::setup::ToolType;
using ncbridge::test_support::make_tool;
using ncbridge::test_support::ToolpathBuilder;

namespace {

std::vector<fr::Layer> layers_of(const ToolpathBuilder& b) {
  auto analysis = fr::analyse_cutter_locations(b.steps(), 0.01);
  for (auto& l : analysis.layers) l.area = fr::swept_area(l.xy_paths(), l.tool.diameter / 2, 0.01);
  return analysis.layers;
}

fr::StrategyAnalysis only_layer(const ToolpathBuilder& b) {
  const auto layers = layers_of(b);
  EXPECT_EQ(layers.size(), 1u);
  return layers.empty() ? fr::StrategyAnalysis{} : fr::analyse_strategy(layers.front());
}

ToolpathBuilder zigzag(double stepover, int passes) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10)).rapid(0, 0, 5).feed(0, 0, -2);
  for (int i = 0; i < passes; ++i) {
    const double y = stepover * i;
    if (i > 0) b.feed(i % 2 ? 60 : 0, y, -2);
    b.feed(i % 2 ? 0 : 60, y, -2);
  }
  return b;
}

}  // namespace

TEST(MillingStrategy, ZigzagIsBidirectionalWithItsStepover) {
  const auto s = only_layer(zigzag(7, 6));
  EXPECT_EQ(s.strategy, fr::Strategy::Bidirectional);
  EXPECT_NEAR(s.stepover, 7, 1e-9);
}

TEST(MillingStrategy, OneWayPassesWithRapidReturnsAreUnidirectional) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10));
  for (int i = 0; i < 5; ++i) b.rapid(0, 6.0 * i, 2).feed(0, 6.0 * i, -1).feed(60, 6.0 * i, -1).rapid(60, 6.0 * i, 2);
  const auto s = only_layer(b);
  EXPECT_EQ(s.strategy, fr::Strategy::Unidirectional);
  EXPECT_NEAR(s.stepover, 6, 1e-9);
}

TEST(MillingStrategy, OneStraightPassIsCenterMilling) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 8)).rapid(10, 10, 5).feed(10, 10, -3).feed(50, 10, -3);
  EXPECT_EQ(only_layer(b).strategy, fr::Strategy::CenterMilling);
}

TEST(MillingStrategy, NestedRectanglesAreContourParallel) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 6)).rapid(20, 20, 5).feed(20, 20, -2);
  for (double d : {0.0, 4.0, 8.0}) {
    const double x0 = 20 - d, y0 = 20 - d, x1 = 60 + d, y1 = 40 + d;
    b.feed(x0, y0, -2).feed(x1, y0, -2).feed(x1, y1, -2).feed(x0, y1, -2).feed(x0, y0, -2);
  }
  const auto s = only_layer(b);
  EXPECT_EQ(s.strategy, fr::Strategy::ContourParallel);
  EXPECT_EQ(s.closed_loops, 3);
}

TEST(MillingStrategy, OneClosedLoopIsAContour) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 6)).rapid(0, 0, 5).feed(0, 0, -2);
  b.feed(100, 0, -2).arc(105, 5, -2, 100, 5, false).feed(105, 50, -2).feed(0, 50, -2).feed(0, 0, -2);
  EXPECT_EQ(only_layer(b).strategy, fr::Strategy::Contour);
}

TEST(MillingStrategy, HelixAboutOneCentreIsHelical) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 6)).rapid(24, 20, 2).feed(24, 20, 0);
  for (int turn = 1; turn <= 4; ++turn) b.arc(24, 20, -2.0 * turn, 20, 20, false);
  b.arc(24, 20, -8, 20, 20, false);  // a flat circle at the bottom
  const auto s = only_layer(b);
  EXPECT_EQ(s.strategy, fr::Strategy::Helical);
  EXPECT_TRUE(s.single_circle);
  EXPECT_NEAR(s.circle_center.x, 20, 1e-9);
  EXPECT_NEAR(s.circle_radius, 4, 1e-9);
}

TEST(MillingStrategy, ManyShortLinkedPassesAtOneLevelAreAdaptive) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 8)).rapid(0, 0, 5).feed(0, 0, -4);
  for (int i = 0; i < 6; ++i) {
    const double x = 3.0 * i;
    b.arc(x + 3, 0, -4, x + 1.5, 0, false).arc(x + 3, 2, -4, x + 3, 1, false).rapid(x + 3, 2, -3.5).rapid(x + 3, 0, -3.5)
        .feed(x + 3, 0, -4);
  }
  EXPECT_EQ(only_layer(b).strategy, fr::Strategy::Adaptive);
}

TEST(CutterLocations, StepDownsAreSeparateLayersAndPlungesAreDrilling) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10)).rapid(0, 0, 5).feed(0, 0, -2).feed(40, 0, -2)
      .feed(40, 0, -4).feed(0, 0, -4).rapid(0, 0, 5);
  b.workingstep(make_tool(2, ToolType::Drill, 5, 118)).drill(10, 10, 2, -12);
  const auto analysis = fr::analyse_cutter_locations(b.steps(), 0.01);
  ASSERT_EQ(analysis.layers.size(), 2u);
  EXPECT_DOUBLE_EQ(analysis.layers[0].z, -2);
  EXPECT_DOUBLE_EQ(analysis.layers[1].z, -4);
  ASSERT_EQ(analysis.drill_passes.size(), 1u);
  EXPECT_DOUBLE_EQ(analysis.drill_passes[0].z_bottom, -12);
  EXPECT_DOUBLE_EQ(analysis.drill_passes[0].at.x, 10);
}

TEST(CutterLocations, SurfaceMachiningIsFreeform) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::BallEndMill, 6)).rapid(0, 0, 5).feed(0, 0, 0);
  for (int i = 1; i <= 40; ++i) b.feed(i, 0, -2 + 2 * std::cos(i * 0.5));
  const auto analysis = fr::analyse_cutter_locations(b.steps(), 0.01);
  ASSERT_EQ(analysis.layers.size(), 1u);
  EXPECT_TRUE(analysis.layers[0].freeform);
}

// examples/plate's face: two passes in opposite senses, the step between them a rapid.
TEST(MillingStrategy, TwoPassesJoinedByARapidAreBidirectional) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FaceMill, 50)).rapid(-30, 15, 2).feed(-30, 15, 0).feed(110, 15, 0);
  b.rapid(110, 45, 0).feed(-30, 45, 0);
  const auto s = only_layer(b);
  EXPECT_EQ(s.strategy, fr::Strategy::Bidirectional);
  EXPECT_NEAR(s.stepover, 30, 1e-9);
}

// A slot ramped down along its centre line and cut back at the level.
TEST(MillingStrategy, BackAndForthOnOneLineIsCentreMilling) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 8)).rapid(10, 10, 2).feed(10, 10, 0);
  b.feed(60, 10, -2).feed(10, 10, -2).feed(60, 10, -2);
  EXPECT_EQ(only_layer(b).strategy, fr::Strategy::CenterMilling);
}

// The generator's contour-parallel finish of a pocket: a loop round the middle entered half-way
// along a side, then the loop along the walls, also entered mid-side. Their long sides step one
// way (77, 63, 54, 86, 54) as a zigzag's would; two large loops make them contours.
TEST(MillingStrategy, TwoNestedLoopsEnteredMidSideAreContourParallel) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 18)).rapid(63, 88, 5).feed(63, 88, -30);
  b.feed(63, 92, -30).feed(77, 92, -30).feed(77, 48, -30).feed(63, 48, -30).feed(63, 88, -30);
  b.feed(54, 88, -30).feed(54, 101, -30).feed(86, 101, -30).feed(86, 39, -30).feed(54, 39, -30).feed(54, 88, -30);
  const auto s = only_layer(b);
  EXPECT_EQ(s.strategy, fr::Strategy::ContourParallel);
  EXPECT_EQ(s.closed_loops, 2);
}

// One loop along a rotated pocket's walls entered part-way along its long side (a vertex splits
// that side in two): one contour, not three passes.
TEST(MillingStrategy, OneLoopWithASplitSideIsAContour) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10)).rapid(52.910, 56.657, 5).feed(52.910, 56.657, -9);
  b.feed(43.141, 52.101, -9).feed(31.766, 46.797, -9).feed(35.572, 38.635, -9).feed(58.234, 49.203, -9).feed(54.428, 57.365, -9);
  b.feed(52.910, 56.657, -9);
  const auto s = only_layer(b);
  EXPECT_EQ(s.strategy, fr::Strategy::Contour);
}

// The generator's milled hole: a helix down to the level at the smallest radius, then flat
// circles from the middle out. The helix is the entry: contour parallel about one centre, still
// helical for the feature (a hole, not a circular pocket).
TEST(MillingStrategy, HelixEntryThenFlatCirclesIsContourParallel) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 6)).rapid(52, 50, 5).feed(52, 50, 0);
  for (double z = 0; z > -3 + 1e-9; z -= 1.5) b.arc(48, 50, z - 0.75, 50, 50, false).arc(52, 50, z - 1.5, 50, 50, false);
  for (double r : {2.0, 5.0, 8.0}) {
    b.feed(50 + r, 50, -3).arc(50 - r, 50, -3, 50, 50, false).arc(50 + r, 50, -3, 50, 50, false);
  }
  const auto layers = layers_of(b);
  ASSERT_FALSE(layers.empty());
  const auto deepest = std::min_element(layers.begin(), layers.end(), [](const auto& a, const auto& c) { return a.z < c.z; });
  const auto s = fr::analyse_strategy(*deepest);
  EXPECT_EQ(s.strategy, fr::Strategy::ContourParallel);
  EXPECT_TRUE(s.helical);
  EXPECT_EQ(s.circle_radii.size(), 3u);
}

namespace {

ncbridge::stepnc::CompositeCurve polyline_curve(std::vector<ncbridge::stepnc::CartesianPoint> points) {
  ncbridge::stepnc::CompositeCurve c;
  c.segments.emplace_back(ncbridge::stepnc::Polyline{std::move(points)});
  return c;
}

}  // namespace

// Two counter-clockwise loops joined by a link, far from the program's origin (p12's open pocket
// at X63..72 Y78..88): the link's run from one loop to the next must not turn the sense the
// level's path sweeps (it did, summed about the origin: a 9 x 10 loop read back clockwise).
TEST(PathDirections, NestedLoopsFarFromTheOriginKeepTheirSense) {
  // A rectangle from (x0, y0), counter-clockwise or clockwise.
  auto loop = [](double x0, double y0, double x1, double y1, bool ccw) {
    if (ccw) return std::vector<ncbridge::stepnc::CartesianPoint>{{x0, y0, -6}, {x1, y0, -6}, {x1, y1, -6}, {x0, y1, -6}, {x0, y0, -6}};
    return std::vector<ncbridge::stepnc::CartesianPoint>{{x0, y0, -6}, {x0, y1, -6}, {x1, y1, -6}, {x1, y0, -6}, {x0, y0, -6}};
  };
  for (const bool ccw : {true, false}) {
    const auto outer = loop(63, 81, 72, 88, ccw), inner = loop(66, 81, 69, 85, ccw);
    std::vector<ncbridge::stepnc::CartesianPoint> level = outer;
    level.insert(level.end(), inner.begin(), inner.end());  // the link: (63, 81) to (66, 81)
    const auto curve = polyline_curve(level);
    const auto d = fr::analyse_path_directions({&curve});
    ASSERT_TRUE(d.rotation.has_value());
    EXPECT_EQ(*d.rotation, ccw ? ncbridge::stepnc::RotDirection::Ccw : ncbridge::stepnc::RotDirection::Cw);
  }
}
