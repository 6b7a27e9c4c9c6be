// Recognition of synthetic toolpaths: each feature type from its cutting area against the stock,
// the material left by earlier cuts, merging of layers and operations, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ncbridge/common/error.hpp"
#include "ncbridge/feature_recognizer/recognizer.hpp"
#include "toolpath_builder.hpp"

namespace fr = ncbridge::feature_recognizer;
using ncbridge::setup::ToolType;
using ncbridge::test_support::make_tool;
using ncbridge::test_support::ToolpathBuilder;

namespace {

ncbridge::setup::Stock block() {
  ncbridge::setup::Stock s;
  s.min = {0, 0, -30};
  s.max = {100, 80, 0};
  return s;
}

// Nested rectangles of path from the centre out (contour parallel), at each level.
void rectangles(ToolpathBuilder& b, double cx, double cy, double half_x, double half_y, double step,
                std::initializer_list<double> levels) {
  for (double z : levels) {
    b.rapid(cx, cy, 2).feed(cx, cy, z);
    for (double d = 0; d <= std::min(half_x, half_y) + 1e-9; d += step) {
      const double x0 = cx - half_x + (std::min(half_x, half_y) - d), x1 = cx + half_x - (std::min(half_x, half_y) - d);
      const double y0 = cy - half_y + (std::min(half_x, half_y) - d), y1 = cy + half_y - (std::min(half_x, half_y) - d);
      b.feed(x0, y0, z).feed(x1, y0, z).feed(x1, y1, z).feed(x0, y1, z).feed(x0, y0, z);
    }
    b.rapid(b.steps().back().moves.back().end.x, b.steps().back().moves.back().end.y, 5);
  }
}

// Zigzag along X over [x0, x1] x [y0, y1] at level z.
void zigzag(ToolpathBuilder& b, double x0, double x1, double y0, double y1, double step, double z) {
  b.rapid(x0, y0, 2).feed(x0, y0, z);
  int i = 0;
  for (double y = y0; y <= y1 + 1e-9; y += step, ++i) {
    if (y > y0) b.feed(i % 2 ? x1 : x0, y, z);
    b.feed(i % 2 ? x0 : x1, y, z);
  }
  b.rapid(i % 2 ? x1 : x0, y1, 5);
}

fr::RecognizedFeature only(const std::vector<fr::RecognizedFeature>& features) {
  EXPECT_EQ(features.size(), 1u);
  return features.empty() ? fr::RecognizedFeature{} : features.front();
}

}  // namespace

TEST(Recognition, EnclosedAreaIsAClosedPocketWithItsRectangularProfile) {
  ToolpathBuilder b;
  b.workingstep(make_tool(2, ToolType::FlatEndMill, 10));
  rectangles(b, 50, 35, 20, 15, 5, {-5, -10});
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::ClosedPocket);
  EXPECT_NEAR(f.x, 50, 0.01);
  EXPECT_NEAR(f.y, 35, 0.01);
  EXPECT_DOUBLE_EQ(f.top_z, 0);
  EXPECT_DOUBLE_EQ(f.bottom_z, -10);
  EXPECT_EQ(f.bottom, fr::BottomCondition::Planar);
  EXPECT_EQ(f.profile.shape, fr::ProfileShape::Rectangular);
  EXPECT_NEAR(f.profile.length, 50, 0.05);
  EXPECT_NEAR(f.profile.width, 40, 0.05);
  EXPECT_NEAR(f.profile.corner_radius, 5, 0.1);
  EXPECT_NEAR(f.profile.angle_deg, 0, 1e-6);
  ASSERT_EQ(f.operations.size(), 1u);
  EXPECT_EQ(f.operations[0].strategy, fr::Strategy::ContourParallel);
  EXPECT_EQ(f.operations[0].layers, 2);
  EXPECT_NEAR(f.operations[0].axial_depth, 5, 1e-9);
  EXPECT_TRUE(f.open_sides.empty());
}

TEST(Recognition, AreaOpenToPartOfOneSideIsAnOpenPocket) {
  ToolpathBuilder b;
  b.workingstep(make_tool(2, ToolType::FlatEndMill, 10));
  zigzag(b, 80, 110, 30, 50, 5, -6);
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::OpenPocket);
  ASSERT_EQ(f.open_sides.size(), 1u);
  EXPECT_EQ(f.open_sides[0], fr::OpenSide::XPlus);
  EXPECT_NEAR(f.x, 87.5, 0.05);  // 75..100 inside the stock
  EXPECT_NEAR(f.y, 40, 0.05);
  EXPECT_DOUBLE_EQ(f.bottom_z, -6);
  EXPECT_EQ(f.operations[0].strategy, fr::Strategy::Bidirectional);
}

TEST(Recognition, AreaAlongAWholeSideIsAStep) {
  ToolpathBuilder b;
  b.workingstep(make_tool(2, ToolType::FlatEndMill, 10));
  for (double z : {-4.0, -8.0}) {
    b.rapid(0, -10, 2).feed(0, -10, z).feed(0, 90, z).feed(8, 90, z).feed(8, -10, z).rapid(8, -10, 5);
  }
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::Step);
  EXPECT_NEAR(f.x, 6.5, 0.05);  // 0..13 inside the stock
  EXPECT_NEAR(f.y, 40, 0.05);
  EXPECT_DOUBLE_EQ(f.bottom_z, -8);
  EXPECT_NE(std::find(f.open_sides.begin(), f.open_sides.end(), fr::OpenSide::XMinus), f.open_sides.end());
}

TEST(Recognition, ConstantWidthAcrossThePartIsAThroughSlot) {
  ToolpathBuilder b;
  b.workingstep(make_tool(3, ToolType::FlatEndMill, 12));
  for (double z : {-2.0, -4.0, -6.0}) b.rapid(-10, 40, 2).feed(-10, 40, z).feed(110, 40, z).rapid(110, 40, 5);
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::Slot);
  EXPECT_FALSE(f.closed());
  EXPECT_NEAR(f.slot_width, 12, 0.05);
  EXPECT_NEAR(f.x, 50, 0.05);
  EXPECT_NEAR(f.y, 40, 0.05);
  EXPECT_DOUBLE_EQ(f.bottom_z, -6);
  EXPECT_EQ(f.operations[0].strategy, fr::Strategy::CenterMilling);
}

TEST(Recognition, CentreLineInsideThePartIsAClosedSlotWithRoundEnds) {
  ToolpathBuilder b;
  b.workingstep(make_tool(3, ToolType::FlatEndMill, 6));
  for (double z : {-1.0, -2.0}) b.rapid(20, 60, 2).feed(20, 60, z).feed(60, 60, z).rapid(60, 60, 5);
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::Slot);
  EXPECT_TRUE(f.closed());
  EXPECT_EQ(f.slot_ends[0], fr::SlotEnd::Radiused);
  EXPECT_NEAR(f.slot_width, 6, 1e-9);
  EXPECT_NEAR(f.x, 40, 0.05);
  ASSERT_EQ(f.slot_course.size(), 2u);
  EXPECT_NEAR(std::abs(f.slot_course[1].x - f.slot_course[0].x), 40, 0.05);
}

TEST(Recognition, AreaCoveringTheWholeTopIsAPlanarFaceEvenWithAnEndMill) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 20));
  zigzag(b, -5, 105, -5, 85, 15, -1);
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::PlanarFace);
  EXPECT_NEAR(f.x, 50, 0.05);
  EXPECT_NEAR(f.y, 40, 0.05);
  EXPECT_DOUBLE_EQ(f.top_z, 0);
  EXPECT_DOUBLE_EQ(f.bottom_z, -1);
  EXPECT_EQ(f.operations[0].type, fr::OperationType::PlaneFinishMilling);
}

TEST(Recognition, ContourAroundThePartIsAGeneralOutsideProfile) {
  ToolpathBuilder b;
  b.workingstep(make_tool(2, ToolType::FlatEndMill, 10));
  b.rapid(-5, -5, 2);
  for (double z : {-10.0, -20.0}) {
    b.feed(-5, -5, z).feed(-5, 75, z).feed(95, 75, z).feed(95, -5, z).feed(-5, -5, z);
  }
  auto stock = block();
  stock.min = {-3, -3, -20};
  stock.max = {93, 73, 0};
  const auto& f = only(fr::recognize(b.steps(), stock));
  EXPECT_EQ(f.type, fr::FeatureType::GeneralOutsideProfile);
  EXPECT_NEAR(f.x, 45, 0.05);
  EXPECT_NEAR(f.y, 35, 0.05);
  EXPECT_DOUBLE_EQ(f.bottom_z, -20);
  EXPECT_EQ(f.bottom, fr::BottomCondition::Through);
  EXPECT_NEAR(f.profile.length, 90, 0.05);
  EXPECT_NEAR(f.profile.width, 70, 0.05);
  EXPECT_EQ(f.operations[0].strategy, fr::Strategy::Contour);
}

TEST(Recognition, HelixIsAMilledRoundHole) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 6)).rapid(54, 40, 2).feed(54, 40, 0);
  for (int turn = 1; turn <= 5; ++turn) b.arc(54, 40, -3.0 * turn, 50, 40, false);
  b.arc(54, 40, -15, 50, 40, false).rapid(54, 40, 5);
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::RoundHole);
  EXPECT_NEAR(f.diameter, 14, 1e-6);
  EXPECT_NEAR(f.x, 50, 1e-6);
  EXPECT_NEAR(f.y, 40, 1e-6);
  EXPECT_DOUBLE_EQ(f.bottom_z, -15);
  EXPECT_EQ(f.operations[0].strategy, fr::Strategy::Helical);
}

TEST(Recognition, DrilledHolesAreThroughWhenThePointBreaksOutElseConical) {
  ToolpathBuilder b;
  b.workingstep(make_tool(4, ToolType::Drill, 8.5, 118)).drill(20, 20, 3, -32).drill(40, 20, 3, -12);
  const auto features = fr::recognize(b.steps(), block());
  ASSERT_EQ(features.size(), 2u);
  EXPECT_EQ(features[0].bottom, fr::BottomCondition::Through);
  EXPECT_DOUBLE_EQ(features[0].bottom_z, -30);
  EXPECT_EQ(features[1].bottom, fr::BottomCondition::Conical);
  EXPECT_DOUBLE_EQ(features[1].bottom_z, -12);
  EXPECT_DOUBLE_EQ(features[1].bottom_angle_deg, 118);
  EXPECT_DOUBLE_EQ(features[1].diameter, 8.5);
  EXPECT_EQ(features[1].operations[0].type, fr::OperationType::Drilling);
}

TEST(Recognition, PecksDrillAndReamAtOnePlaceAreOneHole) {
  ToolpathBuilder b;
  // Pecks: the tool goes back into the hole and feeds on from just above where it stopped.
  b.workingstep(make_tool(2, ToolType::Drill, 20, 118)).drill(20, 60, 5, -10).drill(20, 60, -9, -20).drill(20, 60, -19, -40);
  b.workingstep(make_tool(3, ToolType::Reamer, 22)).drill(20, 60, 5, -40);
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::RoundHole);
  EXPECT_DOUBLE_EQ(f.diameter, 22);
  EXPECT_EQ(f.bottom, fr::BottomCondition::Through);
  ASSERT_EQ(f.operations.size(), 2u);
  EXPECT_EQ(f.operations[0].type, fr::OperationType::MultistepDrilling);
  EXPECT_EQ(f.operations[0].layers, 3);
  EXPECT_EQ(f.operations[1].type, fr::OperationType::Reaming);
  EXPECT_EQ(f.operations[1].workingsteps, std::vector<std::size_t>{1});
}

TEST(Recognition, AHoleDrilledAgainDeeperFromTheSameStartIsDrilling) {
  // Xú et al.'s test part: G81 at three depths, each fed from the R plane (no cycle tag here).
  ToolpathBuilder b;
  b.workingstep(make_tool(2, ToolType::Drill, 20, 118)).drill(20, 60, 5, -10).drill(20, 60, 5, -20).drill(20, 60, 5, -40);
  const auto& f = only(fr::recognize(b.steps(), block()));
  ASSERT_EQ(f.operations.size(), 1u);
  EXPECT_EQ(f.operations[0].type, fr::OperationType::Drilling);
  EXPECT_EQ(f.operations[0].layers, 3);
}

TEST(Recognition, NestedPocketsAreTwoFeaturesTheInnerStartingAtTheOuterFloor) {
  ToolpathBuilder b;
  b.workingstep(make_tool(2, ToolType::FlatEndMill, 10));
  rectangles(b, 50, 40, 25, 15, 5, {-5});
  rectangles(b, 50, 40, 8, 5, 5, {-9, -13});
  const auto features = fr::recognize(b.steps(), block());
  ASSERT_EQ(features.size(), 2u);
  EXPECT_EQ(features[0].type, fr::FeatureType::ClosedPocket);
  EXPECT_EQ(features[1].type, fr::FeatureType::ClosedPocket);
  EXPECT_DOUBLE_EQ(features[0].top_z, 0);
  EXPECT_DOUBLE_EQ(features[0].bottom_z, -5);
  EXPECT_DOUBLE_EQ(features[1].top_z, -5);
  EXPECT_DOUBLE_EQ(features[1].bottom_z, -13);
}

TEST(Recognition, FinishingPassesJoinTheRoughedPocketWithAllowances) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10));
  rectangles(b, 50, 40, 18, 12, 4, {-5, -9.5});  // leaves 1 mm on the walls, 0.5 on the floor
  b.workingstep(make_tool(5, ToolType::FlatEndMill, 8));
  for (double z : {-5.0, -10.0}) {
    b.rapid(30, 26, 2).feed(30, 26, z).feed(70, 26, z).feed(70, 54, z).feed(30, 54, z).feed(30, 26, z).rapid(30, 26, 5);
  }
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::ClosedPocket);
  EXPECT_DOUBLE_EQ(f.bottom_z, -10);
  ASSERT_EQ(f.operations.size(), 2u);
  EXPECT_EQ(f.operations[0].type, fr::OperationType::BottomAndSideRoughMilling);
  EXPECT_EQ(f.operations[1].type, fr::OperationType::BottomAndSideFinishMilling);
  EXPECT_EQ(f.operations[1].tool_number, 5);
  EXPECT_NEAR(f.operations[0].bottom_allowance, 0.5, 1e-9);
  EXPECT_NEAR(f.operations[0].side_allowance, 1.0, 0.1);
}

TEST(Recognition, SurfaceMachiningIsLeftAsARegion) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::BallEndMill, 6)).rapid(10, 10, 5).feed(10, 10, -1);
  for (int row = 0; row < 10; ++row) {
    for (int i = 1; i <= 60; ++i) {
      const double x = row % 2 ? 70 - i : 10 + i;
      b.feed(x, 10 + 4 * row, -3 + 2 * std::cos(x * 0.3));
    }
    b.feed(row % 2 ? 10 : 70, 14 + 4 * row, -1);
  }
  const auto features = fr::recognize(b.steps(), block());
  ASSERT_FALSE(features.empty());
  EXPECT_EQ(features[0].type, fr::FeatureType::Region);
  EXPECT_EQ(features[0].bottom, fr::BottomCondition::General);
}

TEST(Recognition, CuttingOnlyAirRecognisesNothing) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10));
  zigzag(b, 150, 200, 0, 20, 5, -3);
  EXPECT_TRUE(fr::recognize(b.steps(), block()).empty());
}

TEST(Recognition, MillingToolWithoutDiameterIsAnInputError) {
  ToolpathBuilder b;
  b.workingstep(make_tool(7, ToolType::FlatEndMill, 0));
  zigzag(b, 10, 20, 10, 20, 2, -1);
  try {
    fr::recognize(b.steps(), block());
    FAIL() << "expected InputError";
  } catch (const ncbridge::InputError& e) {
    EXPECT_NE(e.message().find("T7"), std::string::npos);
  }
}

TEST(Recognition, NonFiniteCoordinateIsAnInputErrorWithItsLine) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10)).rapid(0, 0, 2);
  auto steps = b.steps();
  fr::Move m;
  m.end = {std::numeric_limits<double>::quiet_NaN(), 0, 0};
  m.source_line = 42;
  steps[0].moves.push_back(m);
  try {
    fr::recognize(steps, block());
    FAIL() << "expected InputError";
  } catch (const ncbridge::InputError& e) {
    EXPECT_EQ(e.where().line, 42u);
  }
}

TEST(Recognition, NoWorkingstepsNoFeatures) { EXPECT_TRUE(fr::recognize({}, block()).empty()); }

// A helix as CC1 gives it (a polyline, no arcs), at two radii: one hole of the outer size.
TEST(Recognition, HelicesAtTwoRadiiAsPolylinesAreOneMilledRoundHole) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 8));
  for (double radius : {2.5, 6.0}) {
    b.rapid(50 + radius, 40, 2).feed(50 + radius, 40, 0.5);
    const int n = 72;
    for (int i = 1; i <= 6 * n; ++i) {  // six turns down to -12 by 2 mm
      const double a = 2 * 3.14159265358979323846 * i / n;
      b.feed(50 + radius * std::cos(a), 40 + radius * std::sin(a), std::max(-12.0, 0.5 - 2.0 * i / n));
    }
    b.feed(50, 40, -12).rapid(50, 40, 5);
  }
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::RoundHole);
  EXPECT_NEAR(f.diameter, 20, 0.01);
  EXPECT_NEAR(f.x, 50, 0.01);
  EXPECT_NEAR(f.y, 40, 0.01);
  EXPECT_DOUBLE_EQ(f.bottom_z, -12);
  EXPECT_EQ(f.operations[0].strategy, fr::Strategy::Helical);
}

// Flat concentric circles at each level clear a circular pocket, not a hole.
TEST(Recognition, FlatConcentricCirclesAreACircularPocket) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 6));
  for (double z : {-3.0, -6.0}) {
    b.rapid(50, 40, 2).feed(50, 40, z);
    for (double r : {2.0, 5.0}) b.feed(50 + r, 40, z).arc(50 + r, 40, z, 50, 40, false);
    b.rapid(55, 40, 5);
  }
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::ClosedPocket);
  EXPECT_EQ(f.profile.shape, fr::ProfileShape::Circular);
  EXPECT_EQ(f.operations[0].strategy, fr::Strategy::ContourParallel);
}

// Passes broken around an island at (50, 65) clear down to -8 around it (keeping the tool centre
// 12 away), as a step or an open pocket with a boss in it is cleared.
void clear_around_island(ToolpathBuilder& b) {
  for (double z : {-4.0, -8.0}) {
    for (double y : {45.0, 53.0, 61.0, 69.0, 77.0, 85.0}) {
      if (std::abs(y - 65) < 12) {
        const double h = std::sqrt(144 - (y - 65) * (y - 65));
        b.rapid(20, y, 2).feed(20, y, z).feed(50 - h, y, z).rapid(50 - h, y, 2);
        b.rapid(50 + h, y, 2).feed(50 + h, y, z).feed(80, y, z).rapid(80, y, 2);
      } else {
        b.rapid(20, y, 2).feed(20, y, z).feed(80, y, z).rapid(80, y, 2);
      }
    }
  }
}

// Then a contour around the material left, that nothing else cuts, above the part bottom: the
// outside profile of a boss, its top where the boss stands.
TEST(Recognition, ContourAroundAStandingIslandIsTheBossOutsideProfile) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10));
  clear_around_island(b);
  b.rapid(61.5, 65, 2);
  for (double z : {-4.0, -8.0}) b.feed(61.5, 65, z).arc(61.5, 65, z, 50, 65, true);
  b.rapid(61.5, 65, 5);
  const auto features = fr::recognize(b.steps(), block());
  ASSERT_EQ(features.size(), 2u);
  EXPECT_EQ(features[0].type, fr::FeatureType::OpenPocket);
  const auto& f = features[1];
  EXPECT_EQ(f.type, fr::FeatureType::GeneralOutsideProfile);
  EXPECT_NEAR(f.x, 50, 0.01);
  EXPECT_NEAR(f.y, 65, 0.01);
  EXPECT_NEAR(f.profile.diameter, 13, 0.05);
  EXPECT_DOUBLE_EQ(f.top_z, 0);
  EXPECT_DOUBLE_EQ(f.bottom_z, -8);
  EXPECT_EQ(f.operations[0].strategy, fr::Strategy::Contour);
}

// The same contour into solid material: a hole bored by circular interpolation (its core
// breaks loose as a chip), not a boss.
TEST(Recognition, CircleIntoSolidMaterialIsABoredRoundHole) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10)).rapid(65, 40, 2);
  for (double z : {-4.0, -8.0}) b.feed(65, 40, z).arc(65, 40, z, 50, 40, true);
  b.rapid(65, 40, 5);
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::RoundHole);
  EXPECT_NEAR(f.diameter, 40, 0.01);
  EXPECT_DOUBLE_EQ(f.bottom_z, -8);
}

// Passes broken around an island (retract, move over, plunge again) are one layer per level,
// and the levels one feature.
TEST(Recognition, PassesBrokenAroundAnIslandAreOneFeature) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10));
  clear_around_island(b);
  const auto features = fr::recognize(b.steps(), block());
  ASSERT_EQ(features.size(), 1u);
  EXPECT_EQ(features[0].type, fr::FeatureType::OpenPocket);
  EXPECT_DOUBLE_EQ(features[0].bottom_z, -8);
  EXPECT_EQ(features[0].operations.size(), 1u);
  EXPECT_EQ(features[0].operations[0].layers, 2);
}

// The outside profile's last level rises over tabs: still one level, one through profile.
TEST(Recognition, TabsOnTheLastLevelOfAnOutsideProfileBelongToThatLevel) {
  ToolpathBuilder b;
  b.workingstep(make_tool(2, ToolType::FlatEndMill, 10)).rapid(-5, -5, 2);
  b.feed(-5, -5, -10).feed(-5, 75, -10).feed(95, 75, -10).feed(95, -5, -10).feed(-5, -5, -10);
  b.feed(-5, -5, -20.5).feed(-5, 30, -20.5).feed(-5, 30, -18).feed(-5, 40, -18).feed(-5, 40, -20.5);
  b.feed(-5, 75, -20.5).feed(95, 75, -20.5).feed(95, -5, -20.5).feed(50, -5, -20.5).feed(50, -5, -18).feed(40, -5, -18);
  b.feed(40, -5, -20.5).feed(-5, -5, -20.5).rapid(-5, -5, 5);
  auto stock = block();
  stock.min = {-3, -3, -20};
  stock.max = {93, 73, 0};
  const auto& f = only(fr::recognize(b.steps(), stock));
  EXPECT_EQ(f.type, fr::FeatureType::GeneralOutsideProfile);
  EXPECT_EQ(f.bottom, fr::BottomCondition::Through);
  EXPECT_DOUBLE_EQ(f.bottom_z, -20);  // the part's bottom, not where the tool went below it
  EXPECT_EQ(f.operations[0].layers, 2);
  EXPECT_EQ(f.operations[0].strategy, fr::Strategy::Contour);
}

// A step between two lower steps: open along all of its side that still stands.
TEST(Recognition, AStepBetweenTwoDeeperStepsIsAStep) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10));
  zigzag(b, 5, 5, -10, 90, 10, -10);   // x- side, 10 wide, to -10 (passes along Y)
  zigzag(b, 95, 95, -10, 90, 10, -10);  // x+ side
  zigzag(b, 0, 100, 3, 3, 10, -4);      // y- side between them, 8 wide, to -4
  const auto features = fr::recognize(b.steps(), block());
  ASSERT_EQ(features.size(), 3u);
  EXPECT_EQ(features[2].type, fr::FeatureType::Step);
  EXPECT_DOUBLE_EQ(features[2].top_z, 0);
  EXPECT_DOUBLE_EQ(features[2].bottom_z, -4);
}

TEST(Recognition, SpotDrillAndTapDoNotSizeTheHole) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::SpotDrill, 12, 90)).drill(30, 30, 5, -2);
  b.workingstep(make_tool(2, ToolType::Drill, 6.8, 118)).drill(30, 30, 5, -20);
  b.workingstep(make_tool(3, ToolType::Tap, 8)).drill(30, 30, 5, -16);
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_DOUBLE_EQ(f.diameter, 6.8);
  ASSERT_EQ(f.operations.size(), 3u);
  EXPECT_EQ(f.operations[0].type, fr::OperationType::CenterDrilling);
  EXPECT_EQ(f.operations[2].type, fr::OperationType::Tapping);
}

// The inner pocket covers most of the outer one's floor (same tool, cut right after it): still
// two features, because its area is not the outer's.
TEST(Recognition, ALargeNestedPocketCutWithTheSameToolIsItsOwnFeature) {
  ToolpathBuilder b;
  b.workingstep(make_tool(2, ToolType::FlatEndMill, 10));
  rectangles(b, 50, 40, 25, 15, 5, {-5});
  rectangles(b, 50, 40, 20, 10, 5, {-9, -13});
  const auto features = fr::recognize(b.steps(), block());
  ASSERT_EQ(features.size(), 2u);
  EXPECT_DOUBLE_EQ(features[0].bottom_z, -5);
  EXPECT_DOUBLE_EQ(features[1].top_z, -5);
  EXPECT_DOUBLE_EQ(features[1].bottom_z, -13);
}

// A stock allowance wider than the tool: one contour cuts the part out and leaves the rest of the
// margin standing (or falling off): still the part's outside profile.
TEST(Recognition, ContourInsideAWideStockMarginIsTheOutsideProfile) {
  ToolpathBuilder b;
  b.workingstep(make_tool(2, ToolType::FlatEndMill, 2));
  b.rapid(-1, -1, 2);
  for (double z : {-5.0, -10.0}) {
    b.feed(-1, -1, z).feed(-1, 71, z).feed(91, 71, z).feed(91, -1, z).feed(-1, -1, z);
  }
  b.rapid(-1, -1, 5);
  auto stock = block();
  stock.min = {-4.5, -4.5, -10};
  stock.max = {94.5, 74.5, 0};
  const auto& f = only(fr::recognize(b.steps(), stock));
  EXPECT_EQ(f.type, fr::FeatureType::GeneralOutsideProfile);
  EXPECT_NEAR(f.x, 45, 0.05);
  EXPECT_NEAR(f.y, 35, 0.05);
  EXPECT_NEAR(f.profile.length, 90, 0.05);
  EXPECT_EQ(f.bottom, fr::BottomCondition::Through);
}

// A pocket not extended beyond the open side: the tool's edge runs along the part's edge (y = 0),
// it does not cross it. Open there all the same.
TEST(Recognition, AreaReachingThePartEdgeWithoutCrossingItIsOpen) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10));
  for (double z : {-3.0, -6.0}) {
    b.rapid(35, 5, 2).feed(35, 5, z).feed(65, 5, z).feed(65, 15, z).feed(35, 15, z).feed(35, 5, z).rapid(35, 5, 5);
  }
  const auto& f = only(fr::recognize(b.steps(), block()));
  EXPECT_EQ(f.type, fr::FeatureType::OpenPocket);
  ASSERT_EQ(f.open_sides.size(), 1u);
  EXPECT_EQ(f.open_sides[0], fr::OpenSide::YMinus);
}

// A pocket on the top level whose side runs out over a step cut deeper before it: open there, and
// placed by the part of it that still had material (not by its extension over the step).
TEST(Recognition, APocketOpeningOntoADeeperStepIsAnOpenPocket) {
  ToolpathBuilder b;
  b.workingstep(make_tool(1, ToolType::FlatEndMill, 10));
  b.rapid(85, -10, 2).feed(85, -10, -10).feed(85, 90, -10).feed(95, 90, -10).feed(95, -10, -10).rapid(95, -10, 5);  // x+ step
  for (double z : {-3.0, -5.0}) {  // x 60..80 extended to 86 over the step, y 30..50, to -5
    b.rapid(65, 35, 2).feed(65, 35, z).feed(81, 35, z).feed(81, 45, z).feed(65, 45, z).feed(65, 35, z).rapid(65, 35, 5);
  }
  const auto features = fr::recognize(b.steps(), block());
  ASSERT_EQ(features.size(), 2u);
  EXPECT_EQ(features[0].type, fr::FeatureType::Step);
  const auto& f = features[1];
  EXPECT_EQ(f.type, fr::FeatureType::OpenPocket);
  EXPECT_NEAR(f.x, 70, 0.1);
  EXPECT_NEAR(f.y, 40, 0.1);
  EXPECT_DOUBLE_EQ(f.top_z, 0);
  EXPECT_DOUBLE_EQ(f.bottom_z, -5);
}
