// The check against features: a pocket cut exactly is reached everywhere with no gouge; the same
// loop 0.1 mm too far out gouges its walls, 0.1 mm too far in leaves them; corners sharper than
// the cutter are unreachable, not leftover; a roughing allowance is allowed.
#include <gtest/gtest.h>

#include "ncbridge/material_check/material_check.hpp"

namespace mc = ncbridge::material_check;
namespace sn = ncbridge::stepnc;

namespace {

// A CC2 model of one 20 x 12 pocket (corner radius `corner`, 5 deep, centred at (20, 10)) cut by
// an 8 mm end mill with `operation`.
sn::Project pocket_project(double corner, sn::Operation operation = sn::BottomAndSideRoughMilling{}) {
  sn::Project p;
  sn::MillingCuttingTool tool;
  tool.its_id = "T1 EM8";
  tool.number = 1;
  tool.body = sn::ToolBody::Endmill;
  tool.dimension.diameter = 8;
  p.tools.push_back(tool);
  p.technologies.emplace_back();
  p.machine_functions.emplace_back();
  sn::ClosedPocket pocket;
  pocket.its_id = "POCKET1";
  pocket.feature_placement.location = {20, 10, 0};
  pocket.depth.position.location = {0, 0, -5};
  pocket.feature_boundary = sn::RectangularClosedProfile{std::nullopt, {12, 0.1, 0.1, 3}, {20, 0.1, 0.1, 3}};
  if (corner > 0) pocket.orthogonal_radius = sn::TolerancedLengthMeasure{corner, 0.1, 0.1, 3};
  p.features.push_back(pocket);
  p.operations.push_back(operation);
  sn::MachiningWorkingstep ws;
  ws.its_id = "WS ROUGH POCKET1";
  p.main_workplan.its_elements.push_back(ws);
  return p;
}

ncbridge::setup::Stock stock() {
  ncbridge::setup::Stock s;
  s.min = {0, 0, -10};
  s.max = {40, 20, 0};
  return s;
}

mc::Motion to(double x, double y, double z, bool rapid = false) {
  mc::Motion m;
  m.end = {x, y, z};
  m.rapid = rapid;
  return m;
}

// A ramp along the loop's first side, then the loop about the pocket's centre, `grow` mm beyond
// the cutter's place at the walls (half sizes 6 x 2 for an 8 mm cutter).
mc::ToolpathProgram loop(double grow) {
  const double x0 = 14 - grow, x1 = 26 + grow, y0 = 8 - grow, y1 = 12 + grow;
  mc::ToolRun run;
  run.workingstep = "WS ROUGH POCKET1";
  run.cutter.radius = 4;
  run.start = {x0, y0, 5};
  run.motions = {to(x0, y0, 0.5, true), to(x1, y0, -5), to(x1, y1, -5), to(x0, y1, -5), to(x0, y0, -5), to(x1, y0, -5),
                 to(x1, y0, 5, true)};
  return {{run}};
}

}  // namespace

TEST(MaterialReport, APocketCutExactlyIsReachedEverywhereWithoutGouge) {
  const auto part = mc::designed_part(pocket_project(4), stock());
  ASSERT_EQ(part.features.size(), 1u);
  EXPECT_DOUBLE_EQ(part.features[0].reach_radius, 4);
  const auto r = mc::check_material(loop(0), part);
  ASSERT_EQ(r.features.size(), 1u);
  const auto& f = r.features[0];
  EXPECT_EQ(f.id, "POCKET1");
  EXPECT_DOUBLE_EQ(f.reached_fraction, 1.0);
  EXPECT_LE(f.max_leftover, 1e-5);
  EXPECT_NEAR(f.area, 20 * 12 - (4 - 3.14159265) * 16, 2.0);  // the rounded rectangle, on 0.1 mm samples
  EXPECT_EQ(f.unreachable_area, 0);
  EXPECT_LE(r.max_gouge, 1e-5);
  EXPECT_EQ(r.gouge_area, 0);
  EXPECT_EQ(r.rapid_collisions, 0u);
  EXPECT_EQ(r.plunges, 0u);
  EXPECT_TRUE(r.clean());
  EXPECT_NEAR(r.removed_volume, 5 * (20 * 12 - (4 - 3.14159265) * 16), 20);
}

TEST(MaterialReport, ALoopTooFarOutGougesTheWalls) {
  const auto r = mc::check_material(loop(0.1), mc::designed_part(pocket_project(4), stock()));
  EXPECT_NEAR(r.max_gouge, 5, 1e-4);  // the whole wall's height, 0.02 mm outside it
  EXPECT_GT(r.gouge_area, 0);
  EXPECT_DOUBLE_EQ(r.features[0].reached_fraction, 1.0);
  EXPECT_FALSE(r.clean());
}

TEST(MaterialReport, ALoopTooFarInLeavesTheWalls) {
  const auto r = mc::check_material(loop(-0.1), mc::designed_part(pocket_project(4), stock()));
  EXPECT_LE(r.max_gouge, 1e-5);
  EXPECT_LT(r.features[0].reached_fraction, 1.0);
  EXPECT_NEAR(r.features[0].max_leftover, 5, 1e-4);
  EXPECT_FALSE(r.clean());
}

TEST(MaterialReport, CornersSharperThanTheCutterAreUnreachableNotLeftover) {
  // Square corners: an 8 mm cutter cannot reach the last (4 - pi) r^2 of each.
  const auto r = mc::check_material(loop(0), mc::designed_part(pocket_project(0), stock()));
  const auto& f = r.features[0];
  EXPECT_NEAR(f.unreachable_area, 4 * (16 - 3.14159265 * 4), 1.0);
  EXPECT_DOUBLE_EQ(f.reached_fraction, 1.0);
  EXPECT_LE(r.max_gouge, 1e-5);
}

TEST(MaterialReport, ARoughingAllowanceIsAllowed) {
  sn::BottomAndSideRoughMilling rough;
  rough.allowance_side = 0.5;
  rough.allowance_bottom = 0.5;
  const auto part = mc::designed_part(pocket_project(4, rough), stock());
  EXPECT_DOUBLE_EQ(part.features[0].allowed_leftover, 0.5);
  EXPECT_DOUBLE_EQ(part.features[0].allowance_side, 0.5);
  // The loop 0.4 mm in and 0.4 mm high: within the allowance (walls are expected where a cutter
  // 0.5 mm larger reaches; at the rounded corners that is more than 0.5 mm off the wall).
  auto program = loop(-0.4);
  for (auto& m : program.runs[0].motions) {
    if (!m.rapid) m.end.z += 0.4;
  }
  const auto r = mc::check_material(program, part);
  EXPECT_DOUBLE_EQ(r.features[0].reached_fraction, 1.0);
  EXPECT_NEAR(r.features[0].max_leftover, 0.4, 1e-4);
}

TEST(MaterialReport, ComparesWhatTwoProgramsRemove) {
  const auto s = stock();
  const auto a = mc::simulate(loop(0), s, 0.1);
  const auto b = mc::simulate(loop(-0.1), s, 0.1);
  const auto same = mc::compare_material(a.grid, a.grid);
  EXPECT_EQ(same.differing_area, 0);
  EXPECT_EQ(same.max_deeper, 0);
  const auto d = mc::compare_material(a.grid, b.grid);
  EXPECT_NEAR(d.max_shallower, 5, 1e-4);  // b leaves 0.1 mm of each wall
  EXPECT_EQ(d.max_deeper, 0);
  EXPECT_NEAR(d.differing_area, 0.1 * 2 * (20 + 12 - 2 * 4 + 2 * 3.14159265 * 4 / 2), 1.5);
  EXPECT_GT(d.volume_a, d.volume_b);
}
