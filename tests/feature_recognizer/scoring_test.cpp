// The scorer's matching rules and the truth reader.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ncbridge/common/error.hpp"
#include "ncbridge/feature_recognizer/scoring.hpp"

namespace fr = ncbridge::feature_recognizer;

namespace {

fr::RecognizedFeature found(fr::FeatureType type, double x, double y, double top, double bottom, double d = 0) {
  fr::RecognizedFeature f;
  f.type = type, f.x = x, f.y = y, f.top_z = top, f.bottom_z = bottom, f.diameter = d;
  return f;
}

fr::TruthFeature truth(fr::FeatureType type, double x, double y, double top, double bottom, bool closed,
                       std::optional<double> d = std::nullopt) {
  fr::TruthFeature t;
  t.type = type, t.x = x, t.y = y, t.top_z = top, t.bottom_z = bottom, t.closed = closed, t.diameter = d;
  return t;
}

}  // namespace

TEST(Scoring, ClosedFeaturesMustBeWithinOneMillimetre) {
  const auto t = truth(fr::FeatureType::ClosedPocket, 10, 10, 0, -5, true);
  EXPECT_EQ(fr::score({found(fr::FeatureType::ClosedPocket, 10.9, 10, 0, -5)}, {t}).overall.matched, 1);
  EXPECT_EQ(fr::score({found(fr::FeatureType::ClosedPocket, 11.1, 10, 0, -5)}, {t}).overall.matched, 0);
}

TEST(Scoring, OpenFeaturesMustBeWithinFiveMillimetres) {
  const auto t = truth(fr::FeatureType::Step, 10, 10, 0, -5, false);
  EXPECT_EQ(fr::score({found(fr::FeatureType::Step, 14.9, 10, 0, -5)}, {t}).overall.matched, 1);
  EXPECT_EQ(fr::score({found(fr::FeatureType::Step, 15.1, 10, 0, -5)}, {t}).overall.matched, 0);
}

TEST(Scoring, TypeDepthsAndDiameterMustAgree) {
  const auto t = truth(fr::FeatureType::RoundHole, 0, 0, 0, -20, true, 8.5);
  EXPECT_EQ(fr::score({found(fr::FeatureType::RoundHole, 0, 0, 0.19, -20.19, 8.54)}, {t}).overall.matched, 1);
  EXPECT_EQ(fr::score({found(fr::FeatureType::RoundHole, 0, 0, 0.21, -20, 8.5)}, {t}).overall.matched, 0);
  EXPECT_EQ(fr::score({found(fr::FeatureType::RoundHole, 0, 0, 0, -20.21, 8.5)}, {t}).overall.matched, 0);
  EXPECT_EQ(fr::score({found(fr::FeatureType::RoundHole, 0, 0, 0, -20, 8.56)}, {t}).overall.matched, 0);
  EXPECT_EQ(fr::score({found(fr::FeatureType::ClosedPocket, 0, 0, 0, -20, 8.5)}, {t}).overall.matched, 0);
}

TEST(Scoring, EachFeatureMatchesOnceClosestFirst) {
  const std::vector<fr::TruthFeature> t{truth(fr::FeatureType::RoundHole, 0, 0, 0, -5, true, 5),
                                        truth(fr::FeatureType::RoundHole, 0.6, 0, 0, -5, true, 5)};
  const std::vector<fr::RecognizedFeature> r{found(fr::FeatureType::RoundHole, 0.5, 0, 0, -5, 5),
                                             found(fr::FeatureType::RoundHole, 0.5, 0, 0, -5, 5),
                                             found(fr::FeatureType::RoundHole, 0.5, 0, 0, -5, 5)};
  const auto s = fr::score(r, t);
  EXPECT_EQ(s.overall.matched, 2);
  EXPECT_EQ(s.overall.recognized, 3);
  EXPECT_NEAR(s.overall.precision(), 2.0 / 3, 1e-12);
  EXPECT_DOUBLE_EQ(s.overall.recall(), 1);
  EXPECT_NEAR(s.overall.f1(), 0.8, 1e-12);
  EXPECT_NEAR(s.mean_position_error(), 0.3, 1e-12);
}

TEST(Scoring, ReadsBothTruthFormatsAndRejectsBadOnes) {
  const auto shared = std::filesystem::path(NCBRIDGE_SHARED_DIR) / "corpus";
  const auto cam = fr::read_truth(shared / "cam/p04_open_pockets/truth.json");
  ASSERT_EQ(cam.size(), 4u);
  EXPECT_EQ(cam[3].type, fr::FeatureType::Slot);
  EXPECT_TRUE(cam[3].closed);  // closed slot with round ends
  EXPECT_FALSE(cam[1].closed);
  const auto paper = fr::read_truth(shared / "paper/truth.json", "test_part.ngc");
  ASSERT_EQ(paper.size(), 3u);
  EXPECT_EQ(paper[2].diameter, 22);
  EXPECT_THROW(fr::read_truth(shared / "paper/truth.json", "nope.ngc"), ncbridge::InputError);
  EXPECT_THROW(fr::read_truth(shared / "does_not_exist.json"), ncbridge::InputError);
  const auto bad = std::filesystem::temp_directory_path() / "ncbridge_recog_bad_truth.json";
  std::ofstream(bad) << R"({"features": [{"id": "X", "type": "blob", "position": [0, 0], "top_z": 0, "bottom_z": 0}]})";
  EXPECT_THROW(fr::read_truth(bad), ncbridge::InputError);
  std::filesystem::remove(bad);
}
