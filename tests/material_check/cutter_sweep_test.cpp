// The simulation on hand-made moves: every cutter shape leaves its own profile, straight and
// arc moves, ramps and helices; rapids report material in their way, plunges are told apart
// from ramps.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ncbridge/material_check/material_check.hpp"
#include "ncbridge/material_check/material_simulation.hpp"

namespace mc = ncbridge::material_check;

namespace {

ncbridge::setup::Stock block() {
  ncbridge::setup::Stock s;
  s.min = {0, 0, -10};
  s.max = {40, 20, 0};
  return s;
}

mc::CutterShape cutter(mc::CutterShape::Kind kind, double radius, double corner = 0, double tip = 118) {
  mc::CutterShape c;
  c.kind = kind;
  c.radius = radius;
  c.corner_radius = corner;
  c.tip_angle = tip;
  return c;
}

mc::Motion feed_to(double x, double y, double z) {
  mc::Motion m;
  m.end = {x, y, z};
  return m;
}

mc::Motion rapid_to(double x, double y, double z) {
  mc::Motion m = feed_to(x, y, z);
  m.rapid = true;
  return m;
}

mc::Motion arc_to(double x, double y, double z, double cx, double cy, double sweep) {
  mc::Motion m = feed_to(x, y, z);
  m.arc_centre = mc::Point2{cx, cy};
  m.arc_sweep = sweep;
  return m;
}

// The height the simulation holds at the grid sample nearest (x, y), and that sample's place.
double height_near(const mc::MaterialSimulation& sim, double x, double y, double* sx = nullptr, double* sy = nullptr) {
  const auto& g = sim.grid();
  const int i = g.first_column(x - g.cell() / 2), j = g.first_row(y - g.cell() / 2);
  if (sx) *sx = g.x(i);
  if (sy) *sy = g.y(j);
  return g.height(i, j);
}

}  // namespace

TEST(CutterSweep, FlatCutterLeavesAStraightTrenchOfItsWidth) {
  mc::MaterialSimulation sim(block(), 0.1);
  const auto c = cutter(mc::CutterShape::Kind::Flat, 3);
  const auto r = sim.feed({-5, 10, -2}, feed_to(45, 10, -2), c);
  EXPECT_TRUE(r.removed);
  const auto& g = sim.grid();
  for (int j = 0; j < g.ny(); ++j) {
    const double y = g.y(j), h = g.height(g.nx() / 2, j);
    if (std::abs(y - 10) < 3 - 1e-6) {
      EXPECT_FLOAT_EQ(h, -2) << y;
    } else if (std::abs(y - 10) > 3 + 1e-6) {
      EXPECT_FLOAT_EQ(h, 0) << y;
    }
  }
  // The removed volume is the trench: 40 long, 6 wide, 2 deep (within a row of samples).
  EXPECT_NEAR(r.removed_volume, 40 * 6 * 2, 40 * 0.2 * 2);
}

TEST(CutterSweep, BallAndBullNoseCuttersLeaveTheirProfiles) {
  for (const auto& [c, name] : {std::pair{cutter(mc::CutterShape::Kind::Ball, 4, 4), "ball"},
                                {cutter(mc::CutterShape::Kind::BullNose, 4, 1.5), "bull nose"}}) {
    mc::MaterialSimulation sim(block(), 0.1);
    sim.feed({-5, 10, -4}, feed_to(45, 10, -4), c);
    for (double d : {0.0, 1.0, 2.0, 2.6, 3.0, 3.9}) {
      double sx, sy;
      const double h = height_near(sim, 20, 10 + d, &sx, &sy);
      EXPECT_NEAR(h, -4 + c.height_at(std::abs(sy - 10)), 1e-5) << name << " at " << d;
    }
  }
}

TEST(CutterSweep, DrillLeavesItsPointAngle) {
  mc::MaterialSimulation sim(block(), 0.05);
  const auto c = cutter(mc::CutterShape::Kind::Cone, 5, 0, 118);
  sim.feed({20, 10, 2}, feed_to(20, 10, -6), c);
  for (double r : {0.0, 1.0, 2.5, 4.0}) {
    double sx, sy;
    const double h = height_near(sim, 20 + r, 10, &sx, &sy);
    const double d = std::hypot(sx - 20, sy - 10);
    EXPECT_NEAR(h, -6 + d / std::tan(59 * std::numbers::pi / 180), 1e-5);
  }
  EXPECT_FLOAT_EQ(height_near(sim, 20 + 5.5, 10), 0);
}

TEST(CutterSweep, ArcCutsAnAnnulusAndLeavesItsCentre) {
  mc::MaterialSimulation sim(block(), 0.1);
  const auto c = cutter(mc::CutterShape::Kind::Flat, 2);
  // A whole turn, radius 7 about (20, 10), clockwise.
  sim.feed({27, 10, -1}, arc_to(27, 10, -1, 20, 10, -2 * std::numbers::pi), c);
  EXPECT_FLOAT_EQ(height_near(sim, 20, 10), 0);          // the core
  EXPECT_FLOAT_EQ(height_near(sim, 20 + 7, 10.05), -1);  // on the path
  EXPECT_FLOAT_EQ(height_near(sim, 20, 10 - 8.5), -1);   // inside the annulus 5..9
  EXPECT_FLOAT_EQ(height_near(sim, 20 + 4.6, 10.05), 0);
  EXPECT_FLOAT_EQ(height_near(sim, 20 - 9.5, 10.05), 0);
  // A quarter arc only reaches its quarter.
  mc::MaterialSimulation quarter(block(), 0.1);
  quarter.feed({27, 10, -1}, arc_to(20, 17, -1, 20, 10, std::numbers::pi / 2), c);
  EXPECT_FLOAT_EQ(height_near(quarter, 20 + 4.95, 10 + 4.95), -1);
  EXPECT_FLOAT_EQ(height_near(quarter, 20 - 4.95, 10 - 4.95), 0);
}

TEST(CutterSweep, RampReachesEachPointAtTheLowestHeightItPassesOverIt) {
  mc::MaterialSimulation sim(block(), 0.1);
  const auto c = cutter(mc::CutterShape::Kind::Flat, 2);
  sim.feed({5, 10, 0}, feed_to(35, 10, -3), c);
  // Over (20, 10) the cutter passes from x = 18 to 22: the lowest there is at x = 22.
  double sx, sy;
  const double h = height_near(sim, 20, 10, &sx, &sy);
  const double reach = std::sqrt(4 - (sy - 10) * (sy - 10));
  EXPECT_NEAR(h, -3 * (sx + reach - 5) / 30, 1e-5);
  // A ball cutter on the same ramp: each point at its exact lowest (golden-section search).
  mc::MaterialSimulation ball(block(), 0.1);
  const auto b = cutter(mc::CutterShape::Kind::Ball, 2, 2);
  ball.feed({5, 10, 0}, feed_to(35, 10, -3), b);
  const double hb = height_near(ball, 20, 10, &sx, &sy);
  double expected = 1e9;
  for (int k = 0; k <= 200000; ++k) {  // brute force over the move
    const double t = k / 200000.0, x = 5 + 30 * t, z = -3 * t;
    const double d = std::hypot(sx - x, sy - 10);
    if (d <= 2) expected = std::min(expected, z + b.height_at(d));
  }
  EXPECT_NEAR(hb, expected, 1e-4);
}

TEST(CutterSweep, HelixCutsLikeItsPlanarCircleAtTheBottom) {
  mc::MaterialSimulation sim(block(), 0.1);
  const auto c = cutter(mc::CutterShape::Kind::Flat, 3);
  // Two turns down from 0 to -4 about (20, 10), radius 3, then a flat turn at -4.
  sim.feed({23, 10, 0}, arc_to(23, 10, -4, 20, 10, 4 * std::numbers::pi), c);
  sim.feed({23, 10, -4}, arc_to(23, 10, -4, 20, 10, 2 * std::numbers::pi), c);
  for (double d : {0.0, 2.0, 4.0, 5.9}) EXPECT_FLOAT_EQ(height_near(sim, 20 + d, 10.05), -4) << d;
  EXPECT_FLOAT_EQ(height_near(sim, 20 + 6.1, 10.05), 0);
}

TEST(CutterSweep, RapidsReportMaterialInTheirWay) {
  mc::MaterialSimulation sim(block(), 0.1);
  const auto c = cutter(mc::CutterShape::Kind::Flat, 3);
  EXPECT_EQ(sim.penetration({-5, 10, 5}, rapid_to(45, 10, 5), c), 0);       // above the top
  EXPECT_NEAR(sim.penetration({-5, 10, -1}, rapid_to(45, 10, -1), c), 1, 1e-6);  // through it
  EXPECT_EQ(sim.penetration({-5, 10, -1}, rapid_to(-5, 30, -1), c), 0);     // beside the stock
  sim.feed({-5, 10, -2}, feed_to(45, 10, -2), c);
  EXPECT_EQ(sim.penetration({-5, 10, -1}, rapid_to(45, 10, -1), c), 0);     // in its own trench
  // Nothing was removed by the rapids.
  EXPECT_FLOAT_EQ(height_near(sim, 20, 16), 0);
}

TEST(CutterSweep, ProgramCountsRapidsThroughMaterialAndPlungesButNotRampsOrDrills) {
  ncbridge::setup::Stock stock = block();
  mc::DesignedPart part;
  part.stock = stock;
  mc::ToolRun mill;
  mill.workingstep = "WS MILL";
  mill.cutter = cutter(mc::CutterShape::Kind::Flat, 3);
  mill.start = {10, 10, 5};
  mill.motions = {feed_to(10, 10, -2),                          // a plunge into material
                  rapid_to(30, 10, -1),                         // a rapid through it, from -2 up
                  rapid_to(30, 10, 5), rapid_to(5, 4, 5),
                  feed_to(35, 4, -2)};                          // a ramp (4 degrees)
  mc::ToolRun drill;
  drill.workingstep = "WS DRILL";
  drill.drilling = true;
  drill.cutter = cutter(mc::CutterShape::Kind::Cone, 2.5);
  drill.start = {20, 16, 5};
  drill.motions = {feed_to(20, 16, -6), rapid_to(20, 16, 5)};
  const auto report = mc::check_material({{mill, drill}}, part);
  EXPECT_EQ(report.plunges, 1u);
  EXPECT_NEAR(report.max_plunge_depth, 2, 1e-6);
  EXPECT_EQ(report.rapid_collisions, 1u);
  EXPECT_NEAR(report.max_rapid_depth, 2, 1e-3);  // it leaves the plunge's hole at -2
  ASSERT_EQ(report.findings.size(), 2u);
  EXPECT_EQ(report.findings[0].kind, mc::Finding::Kind::Plunge);
  EXPECT_EQ(report.findings[0].workingstep, "WS MILL");
  EXPECT_EQ(report.findings[1].kind, mc::Finding::Kind::RapidThroughMaterial);
}
