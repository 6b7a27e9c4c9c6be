// Programs the project already converts, checked against the features recognised in them: the
// check finds what is really there (checked by hand against each program and cross-checked
// with formulas where one exists).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ncbridge/material_check/material_check.hpp"
#include "program_pipeline.hpp"

namespace mc = ncbridge::material_check;
namespace ts = ncbridge::test_support;

namespace {

struct Checked {
  ts::PipelineResult pipeline;
  mc::MaterialReport report;
};

Checked check(const std::string& name, double cell = 0.2) {
  const auto part = ts::corpus_part(name);
  Checked c;
  c.pipeline = ts::run_forward_pipeline(part.program, part.tools, part.stock);
  mc::CheckOptions o;
  o.cell = cell;
  c.report = mc::check_material(mc::program_from_stepnc(c.pipeline.cc2), mc::designed_part(c.pipeline.cc2, c.pipeline.stock), o);
  return c;
}

const mc::FeatureFigures& feature(const mc::MaterialReport& r, const std::string& id) {
  for (const auto& f : r.features) {
    if (f.id == id) return f;
  }
  throw std::runtime_error("no feature " + id);
}

}  // namespace

TEST(CorpusMaterial, ThePapersFaceMillingIsClean) {
  const auto c = check("face_mill");
  EXPECT_TRUE(c.report.clean()) << c.report.max_gouge;
  ASSERT_EQ(c.report.features.size(), 1u);
  EXPECT_NEAR(c.report.features[0].area, 100 * 120, 60);
  // 5 mm off 100 x 120 (the passes run out over the stock's sides, where there is nothing).
  EXPECT_NEAR(c.report.removed_volume, 5 * 100 * 120, 600);
}

TEST(CorpusMaterial, ThePapersTestPartReachesEveryFeature) {
  const auto c = check("test_part");
  const auto& r = c.report;
  EXPECT_EQ(r.rapid_collisions, 0u);
  for (const auto& f : r.features) EXPECT_GE(f.reached_fraction, 0.999) << f.id;
  // Its roughing plunges the end mill at the pocket's centre, once per level (5 levels, and the
  // finishing pass's last 0.5 mm).
  EXPECT_EQ(r.plunges, 6u);
  // The recognised pocket's corners are rounder than the cut by a few hundredths of a mm: the
  // only places cut "deeper than the part" are thin slivers there.
  EXPECT_LT(r.gouge_area, 1.0);
}

TEST(CorpusMaterial, ThroughHolesDrilledShortOfTheirPointStillStandAtTheEdge) {
  // p01's 10 mm holes are drilled 1.5 mm below the 30 mm part: the 118 degree point needs
  // 5 / tan(59) = 3.0 mm to clear the full diameter, so a ring 1.5 mm high stays at the edge.
  const auto c = check("p01_block_reference", 0.1);
  const double expected = 5 / std::tan(59 * std::numbers::pi / 180) - 1.5;
  for (const char* id : {"HOLE1 D=10MM", "HOLE2 D=10MM"}) {
    const auto& f = feature(c.report, id);
    EXPECT_NEAR(f.max_leftover, expected, 0.01) << id;
    EXPECT_LT(f.reached_fraction, 1.0);
  }
  for (const char* id : {"PLANAR FACE1", "PROFILE1", "POCKET1", "SLOT1", "STEP1"}) {
    EXPECT_GE(feature(c.report, id).reached_fraction, 0.9999) << id;
  }
  EXPECT_EQ(c.report.rapid_collisions, 0u);
}

TEST(CorpusMaterial, ABoreByOneCirclePerLevelLeavesItsCore) {
  // p12's 22 mm blind bore: one circle of radius 8 per level with a 6 mm cutter leaves a core of
  // radius 5 standing the whole 9 mm depth; its other features are cut.
  const auto c = check("p12_freecad_style");
  const auto& bore = feature(c.report, "HOLE3 D=22MM");
  EXPECT_NEAR(bore.max_leftover, 9, 1e-3);
  EXPECT_NEAR(bore.reached_fraction, 1 - 3.14159265 * 25 / (3.14159265 * 121), 0.02);
  for (const char* id : {"HOLE1 D=9MM", "HOLE2 D=15MM", "POCKET1", "POCKET2", "STEP1", "OPEN POCKET2"}) {
    EXPECT_GE(feature(c.report, id).reached_fraction, 0.9999) << id;
  }
}

TEST(CorpusMaterial, RapidsBelowTheBlanksTopAreFound) {
  // p09's program keeps its safe height at Z5, under the top of its 8 mm blank: its first
  // rapid moves after the face go through material.
  const auto c = check("p09_small_part");
  EXPECT_GT(c.report.rapid_collisions, 0u);
  ASSERT_FALSE(c.report.findings.empty());
  bool found = false;
  for (const auto& f : c.report.findings) {
    if (f.kind == mc::Finding::Kind::RapidThroughMaterial && std::abs(f.to.z - 5) < 1e-9) found = true;
  }
  EXPECT_TRUE(found);
}

TEST(CorpusMaterial, HelicalHoleMillingIsClean) {
  const auto c = check("p07_helix_holes");
  EXPECT_EQ(c.report.rapid_collisions, 0u);
  EXPECT_EQ(c.report.plunges, 0u);
  EXPECT_LE(c.report.max_gouge, 0.01);
  for (const auto& f : c.report.features) EXPECT_GE(f.reached_fraction, 0.9999) << f.id;
}
