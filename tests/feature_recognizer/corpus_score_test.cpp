// Recognition of the corpus (5 FreeCAD parts, 2 programs of Xú et al. 2014, 7 hand-designed
// parts of other shapes and strategies), comments stripped, scored against truth: F1 >= 0.95 on
// every program; every operation the truth lists (ISO 14649 "operations", or FreeCAD's
// "machined_by" mapped to ISO 14649) is recognised with its type (drilling, peck drilling,
// milling; roughing or finishing), tool and strategy.
#include <gtest/gtest.h>

#include "recognition_corpus.hpp"

namespace fr = ncbridge::feature_recognizer;
namespace ts = ncbridge::test_support;

namespace {

std::vector<ts::RecognitionCase> corpus() { return ts::recognition_corpus(NCBRIDGE_SOURCE_DIR, NCBRIDGE_SHARED_DIR); }

ts::RecognitionCase named(const std::string& name) {
  for (const auto& c : corpus()) {
    if (c.name == name) return c;
  }
  ADD_FAILURE() << "no case " << name;
  return {};
}

}  // namespace

class CorpusScore : public testing::TestWithParam<std::string> {};

TEST_P(CorpusScore, F1AtLeast95Percent) {
  const auto c = named(GetParam());
  const auto features = ts::recognize_case(c);
  const auto s = fr::score(features, fr::read_truth(c.truth, c.truth_program));
  for (const auto& [type, t] : s.per_type) {
    EXPECT_GE(t.f1(), 0.95) << fr::to_string(type) << ": truth " << t.truth << ", found " << t.recognized
                            << ", matched " << t.matched;
  }
  EXPECT_GE(s.overall.f1(), 0.95);
  RecordProperty("f1", std::to_string(s.overall.f1()));
}

TEST_P(CorpusScore, OperationsOfTheMatchedFeaturesAgreeWithTruth) {
  const auto c = named(GetParam());
  const auto features = ts::recognize_case(c);
  const auto truth = fr::read_truth(c.truth, c.truth_program);
  const auto s = fr::score(features, truth);
  const auto ops = fr::score_operations(features, truth, s);
  ASSERT_GT(ops.truth, 0) << "the truth lists no operations";
  for (const auto& m : s.matches) {
    const auto& t = truth[m.truth_index];
    const auto& r = features[m.recognized_index];
    std::string want, got;
    for (const auto& o : t.operations) {
      std::string strategies;
      for (auto st : o.strategies) strategies += (strategies.empty() ? "" : "|") + std::string(fr::to_string(st));
      want += std::string(fr::to_string(o.type)) + " T" + std::to_string(o.tool_number) + " " +
              (strategies.empty() ? "?" : strategies) + " (" + o.source + "); ";
    }
    for (const auto& o : r.operations) {
      got += std::string(fr::to_string(o.type)) + " T" + std::to_string(o.tool_number) + " " + std::string(fr::to_string(o.strategy)) + "; ";
    }
    if (!t.operations.empty()) {
      EXPECT_EQ(fr::score_operations({r}, {t}, {{}, {}, {{0, 0, 0}}}).matched, static_cast<int>(t.operations.size()))
          << t.id << ": recognised " << got << " truth " << want;
    }
  }
  EXPECT_EQ(ops.matched, ops.truth);
  EXPECT_EQ(ops.recognized, ops.truth);
}

// A closed pocket finished by passes along its boundary (contour, contour parallel, or a zigzag
// with a contour) has its outline set by the toolpath: length, width, corner radius or 45° corner
// chamfer, or diameter within 0.02 mm of the design; so has an outside profile (the part's
// outline, cut by a contour). Chamfered corners are chamfers, not radii. (A zigzag alone leaves
// a pocket's corners to the stepover; FreeCAD's adaptive path is itself a polyline within its
// own tolerance.)
TEST_P(CorpusScore, ClosedOutlinesWithin002mmWhereTheToolpathSetsThem) {
  const auto c = named(GetParam());
  const auto features = ts::recognize_case(c);
  const auto truth = fr::read_truth(c.truth, c.truth_program);
  int compared = 0;
  for (const auto& m : fr::score(features, truth).matches) {
    const auto& t = truth[m.truth_index];
    const auto& r = features[m.recognized_index];
    if (r.operations.empty()) continue;
    if (t.type == fr::FeatureType::ClosedPocket) {
      const auto last = r.operations.back().strategy;
      if (last != fr::Strategy::Contour && last != fr::Strategy::ContourParallel &&
          last != fr::Strategy::BidirectionalContour && last != fr::Strategy::ContourBidirectional) {
        continue;
      }
    } else if (t.type != fr::FeatureType::GeneralOutsideProfile) {
      continue;
    }
    if (t.profile_diameter) {
      EXPECT_EQ(r.profile.shape, fr::ProfileShape::Circular) << t.id;
      EXPECT_NEAR(r.profile.diameter, *t.profile_diameter, 0.02) << t.id;
      ++compared;
    }
    if (t.length && t.width) {
      EXPECT_NEAR(r.profile.length, *t.length, 0.02) << t.id;
      EXPECT_NEAR(r.profile.width, *t.width, 0.02) << t.id;
    }
    if (t.length && t.width && t.corner_radius) {
      EXPECT_EQ(r.profile.shape, fr::ProfileShape::Rectangular) << t.id;
      EXPECT_NEAR(r.profile.corner_radius, *t.corner_radius, 0.02) << t.id;
      ++compared;
    }
    if (t.length && t.width && t.corner_chamfer) {
      EXPECT_EQ(r.profile.shape, fr::ProfileShape::GeneralClosed) << t.id;
      EXPECT_EQ(r.profile.corner_radius, 0) << t.id;
      EXPECT_NEAR(r.profile.corner_chamfer, *t.corner_chamfer, 0.02) << t.id;
      ++compared;
    }
  }
  RecordProperty("compared", std::to_string(compared));
}

INSTANTIATE_TEST_SUITE_P(Parts, CorpusScore,
                         testing::Values("p01_block_reference", "p02_plate_center_zero", "p03_bracket_steps",
                                         "p04_open_pockets", "p05_slots", "paper_face_mill", "paper_test_part",
                                         "p06_nested_pockets", "p07_helix_holes", "p08_multi_level", "p09_small_part",
                                         "p10_plate", "p11_slots_rotated_pocket", "p12_freecad_style",
                                         "p13_hsm_style", "p14_shop_program", "p15_hobby_style"));

TEST(PaperPrograms, FaceMillIsExactlyOneBidirectionalPlanarFaceOfDepthFive) {
  const auto features = ts::recognize_case(named("paper_face_mill"));
  ASSERT_EQ(features.size(), 1u);
  const auto& f = features[0];
  EXPECT_EQ(f.type, fr::FeatureType::PlanarFace);
  EXPECT_DOUBLE_EQ(f.depth(), 5);
  ASSERT_EQ(f.operations.size(), 1u);
  EXPECT_EQ(f.operations[0].type, fr::OperationType::PlaneFinishMilling);
  EXPECT_EQ(f.operations[0].strategy, fr::Strategy::Bidirectional);
  EXPECT_NEAR(f.operations[0].radial_depth, 17.1, 1e-6);
  EXPECT_NEAR(f.profile.length, 120, 0.01);  // along Y, the passes' direction
}

TEST(PaperPrograms, TestPartPocketIsRoughedThenFinishedAndTheHoleDrilledThenReamed) {
  const auto features = ts::recognize_case(named("paper_test_part"));
  ASSERT_EQ(features.size(), 3u);
  const auto& face = features[0];
  EXPECT_EQ(face.type, fr::FeatureType::PlanarFace);
  ASSERT_EQ(face.operations.size(), 1u);
  EXPECT_EQ(face.operations[0].layers, 2);
  EXPECT_NEAR(face.operations[0].axial_depth, 2.5, 1e-9);

  const auto& pocket = features[1];
  EXPECT_EQ(pocket.type, fr::FeatureType::ClosedPocket);
  EXPECT_EQ(pocket.profile.shape, fr::ProfileShape::Rectangular);
  EXPECT_NEAR(pocket.profile.length, 80, 0.05);
  EXPECT_NEAR(pocket.profile.width, 50, 0.05);
  EXPECT_NEAR(pocket.profile.corner_radius, 10, 0.2);
  EXPECT_NEAR(pocket.profile.angle_deg, 90, 1e-6);
  ASSERT_EQ(pocket.operations.size(), 2u);
  EXPECT_EQ(pocket.operations[0].type, fr::OperationType::BottomAndSideRoughMilling);
  EXPECT_EQ(pocket.operations[0].layers, 5);
  EXPECT_NEAR(pocket.operations[0].bottom_allowance, 0.5, 1e-9);
  EXPECT_NEAR(pocket.operations[0].side_allowance, 1.0, 0.05);
  EXPECT_EQ(pocket.operations[1].type, fr::OperationType::BottomAndSideFinishMilling);
  EXPECT_EQ(pocket.operations[1].layers, 6);

  const auto& hole = features[2];
  EXPECT_EQ(hole.type, fr::FeatureType::RoundHole);
  EXPECT_EQ(hole.bottom, fr::BottomCondition::Through);
  ASSERT_EQ(hole.operations.size(), 2u);
  EXPECT_EQ(hole.operations[0].tool_number, 2);
  EXPECT_EQ(hole.operations[1].type, fr::OperationType::Reaming);
}
