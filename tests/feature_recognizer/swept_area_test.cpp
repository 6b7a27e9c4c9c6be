// The geometry under recognition: swept areas of lines, arcs and zigzags, and region algebra.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "region.hpp"
#include "swept_area.hpp"

namespace fr = ncbridge::feature_recognizer;
using std::numbers::pi;

namespace {
constexpr double kTol = 0.01;
// An inscribed polygon loses at most tolerance * perimeter of area.
double area_bound(double perimeter) { return 2 * kTol * perimeter; }
}  // namespace

TEST(SweptArea, StraightLineIsAStadium) {
  const double r = 5, length = 40;
  const auto area = fr::swept_area({{{0, 0}, {length, 0}}}, r, kTol);
  const double exact = 2 * r * length + pi * r * r;
  EXPECT_NEAR(area.area(), exact, area_bound(2 * length + 2 * pi * r));
  EXPECT_LE(area.area(), exact);  // inscribed: never more than the true swept area
  const auto box = *area.bbox();
  EXPECT_NEAR(box.xmin, -r, kTol);
  EXPECT_NEAR(box.xmax, length + r, kTol);
  EXPECT_NEAR(box.ymax - box.ymin, 2 * r, 2 * kTol);
  EXPECT_TRUE(area.contains({20, 4.9}));
  EXPECT_FALSE(area.contains({20, 5.1}));
}

TEST(SweptArea, RepeatedPointsAreTheSameSweep) {
  // A move of no length between two others (a program's G1 to where the tool already is, as a
  // Heidenhain program's repeated L block makes): no direction of its own, the same area.
  const auto plain = fr::swept_area({{{0, 0}, {10, 0}, {10, 5}}}, 2, kTol);
  const auto repeated = fr::swept_area({{{0, 0}, {0, 0}, {10, 0}, {10, 0}, {10, 5}, {10, 5}}}, 2, kTol);
  EXPECT_DOUBLE_EQ(repeated.area(), plain.area());
  EXPECT_NEAR(fr::swept_area({{{3, 4}, {3, 4}}}, 2, kTol).area(), fr::swept_area({{{3, 4}}}, 2, kTol).area(), 1e-9);
}

TEST(SweptArea, SinglePointIsADisk) {
  const auto area = fr::swept_area({{{3, 4}}}, 2, kTol);
  EXPECT_NEAR(area.area(), pi * 4, area_bound(2 * pi * 2));
}

TEST(SweptArea, ArcSweepsAnAnnularSector) {
  // A quarter circle of radius 20 about the origin, tool radius 4, as chords within kTol.
  std::vector<fr::Point2> arc;
  const int n = 400;
  for (int i = 0; i <= n; ++i) arc.push_back({20 * std::cos(pi / 2 * i / n), 20 * std::sin(pi / 2 * i / n)});
  const auto area = fr::swept_area({arc}, 4, kTol);
  const double exact = pi / 4 * (24 * 24 - 16 * 16) + pi * 16;  // sector of the ring + two half disks
  EXPECT_NEAR(area.area(), exact, 0.5);
  EXPECT_TRUE(area.contains({0, 23.9}));
  EXPECT_FALSE(area.contains({0, 15.9}));
  EXPECT_FALSE(area.contains({10, 10}));  // inside the arc, beyond the tool
}

TEST(SweptArea, ZigzagCoversItsRectangleWithoutGaps) {
  // Passes 8 mm apart with a 10 mm tool: the union is one region with no holes.
  std::vector<fr::Point2> zigzag;
  for (int i = 0; i <= 5; ++i) {
    const double y = 8.0 * i;
    if (i % 2 == 0) zigzag.insert(zigzag.end(), {{0, y}, {50, y}});
    else zigzag.insert(zigzag.end(), {{50, y}, {0, y}});
  }
  const auto area = fr::swept_area({zigzag}, 5, kTol);
  const auto parts = area.polygons();
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_TRUE(parts[0].holes.empty());
  EXPECT_TRUE(area.contains({25, 20}));
  // Inside the rectangle -5..55 x -5..45, short of it only by the rounded ends of the passes.
  EXPECT_LT(area.area(), 60 * 50);
  EXPECT_GT(area.area(), 60 * 50 - 6 * (4 - pi) * 25);
  const auto box = *area.bbox();
  EXPECT_NEAR(box.width(), 60, 2 * kTol);
  EXPECT_NEAR(box.height(), 50, 2 * kTol);
}

TEST(SweptArea, WidePassesLeaveRidgesAsHoles) {
  // A closed square loop 40 mm wide with a 10 mm tool leaves an island: a ring.
  const auto ring = fr::swept_area({{{0, 0}, {40, 0}, {40, 40}, {0, 40}, {0, 0}}}, 5, kTol);
  const auto parts = ring.polygons();
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].holes.size(), 1u);
  EXPECT_FALSE(ring.contains({20, 20}));
  EXPECT_TRUE(ring.filled().contains({20, 20}));
  EXPECT_NEAR(ring.filled().minus(ring).area(), 30 * 30, 0.5);
}

TEST(SweptArea, SimplifyKeepsShapeWithinTolerance) {
  std::vector<fr::Point2> line;
  for (int i = 0; i <= 100; ++i) line.push_back({static_cast<double>(i), 0.001 * (i % 2)});
  const auto simple = fr::simplify_polyline(line, kTol);
  ASSERT_EQ(simple.size(), 2u);
  EXPECT_EQ(simple.front(), line.front());
  EXPECT_EQ(simple.back(), line.back());
  const std::vector<fr::Point2> corner{{0, 0}, {10, 0}, {10, 10}};
  EXPECT_EQ(fr::simplify_polyline(corner, kTol).size(), 3u);
}

TEST(Region, BooleanOperationsAreExact) {
  const auto a = fr::Region::rectangle({0, 0, 10, 10});
  const auto b = fr::Region::rectangle({5, 5, 15, 15});
  EXPECT_DOUBLE_EQ(a.united(b).area(), 175);
  EXPECT_DOUBLE_EQ(a.intersected(b).area(), 25);
  EXPECT_DOUBLE_EQ(a.minus(b).area(), 75);
  EXPECT_DOUBLE_EQ(fr::overlap_ratio(a, b), 25.0 / 175.0);
  const auto apart = a.united(fr::Region::rectangle({20, 0, 30, 10}));
  EXPECT_EQ(apart.components().size(), 2u);
  EXPECT_TRUE(fr::Region().empty());
  EXPECT_DOUBLE_EQ(fr::Region().area(), 0);
}

TEST(Region, DegeneratePolygonsAreIgnored) {
  EXPECT_TRUE(fr::Region::polygon({{0, 0}, {1, 1}, {2, 2}}).empty());
  EXPECT_TRUE(fr::Region::polygon({{0, 0}, {0, 0}}).empty());
}

TEST(Region, BoundaryBandStraddlesTheOutline) {
  const auto box = fr::Region::rectangle({0, 0, 100, 50});
  const auto band = fr::boundary_band(box, 0.5, kTol);
  EXPECT_TRUE(band.contains({100.4, 25}));
  EXPECT_TRUE(band.contains({99.6, 25}));
  EXPECT_FALSE(band.contains({50, 25}));
  EXPECT_NEAR(band.minus(box).area(), 0.5 * 300 + pi * 0.25, 0.05);
}
