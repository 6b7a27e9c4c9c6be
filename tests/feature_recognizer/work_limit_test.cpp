// The bound on exact work (docs/recognition.md, "Bounded cost"): a program of dense random cuts
// under a small work limit is recognised exactly up to the limit and coarsely after it, every
// workingstep still in exactly one operation, the same way every time; without a limit nothing
// is approximate, and the corpus never comes near the default limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "ncbridge/feature_recognizer/recognizer.hpp"
#include "recognition_corpus.hpp"
#include "toolpath_builder.hpp"

namespace fr = ncbridge::feature_recognizer;
namespace ts = ncbridge::test_support;
using ncbridge::setup::ToolType;

namespace {

ncbridge::setup::Stock plate() {
  ncbridge::setup::Stock s;
  s.min = {0, 0, -30};
  s.max = {200, 150, 0};
  return s;
}

// Levels of random long strokes of a 6 mm end mill at random depths, each level its own
// workingstep (as the interpreter benchmark's program cuts), and a hole drilled now and then.
std::vector<fr::ToolpathWorkingstep> random_strokes(int levels) {
  ts::ToolpathBuilder b;
  unsigned seed = 2024;
  auto next = [&seed](double high) {
    seed = seed * 1103515245u + 12345u;
    return static_cast<double>((seed >> 8) % 100000) / 100000.0 * high;
  };
  const auto mill = ts::make_tool(1, ToolType::FlatEndMill, 6);
  const auto drill = ts::make_tool(2, ToolType::Drill, 5, 118);
  for (int level = 0; level < levels; ++level) {
    b.workingstep(mill);
    const double z = -0.5 - next(9);
    b.rapid(next(200), next(150), 5).feed(b.steps().back().moves.back().end.x, b.steps().back().moves.back().end.y, z);
    for (int k = 0; k < 12; ++k) b.feed(next(200), next(150), z);
    b.rapid(b.steps().back().moves.back().end.x, b.steps().back().moves.back().end.y, 5);
    if (level % 10 == 9) {
      b.workingstep(drill);
      b.drill(10 + next(180), 10 + next(130), 2, -12);
    }
  }
  return b.steps();
}

// Every workingstep of the input in exactly one operation of one feature.
void expect_every_workingstep_once(const std::vector<fr::RecognizedFeature>& features, std::size_t count) {
  std::vector<int> seen(count, 0);
  for (const auto& f : features) {
    for (const auto& op : f.operations) {
      for (auto w : op.workingsteps) {
        ASSERT_LT(w, count);
        ++seen[w];
      }
    }
  }
  for (std::size_t w = 0; w < count; ++w) EXPECT_EQ(seen[w], 1) << "workingstep " << w;
}

}  // namespace

TEST(WorkLimit, PastTheLimitCutsAreCoarseRegionsAndNothingIsLost) {
  const auto program = random_strokes(30);
  fr::Options tight;
  tight.work_base = 9e3;
  tight.work_per_point = 1;
  const auto features = fr::recognize(program, plate(), tight);
  std::size_t approximate = 0, coarse_regions = 0;
  for (const auto& f : features) {
    approximate += f.approximate ? 1 : 0;
    if (f.approximate && f.type == fr::FeatureType::Region && f.bottom == fr::BottomCondition::General) {
      ++coarse_regions;
      // A coarse region is the box its paths sweep, from its lowest level.
      EXPECT_EQ(f.profile.outline.size(), 4u);
      EXPECT_LT(f.bottom_z, 0);
    }
  }
  EXPECT_GT(approximate, 0u);
  EXPECT_GT(coarse_regions, 0u);
  EXPECT_LT(approximate, features.size());  // the start is exact
  expect_every_workingstep_once(features, program.size());

  // The same input gives the same features: the work is counted, not timed.
  const auto again = fr::recognize(program, plate(), tight);
  ASSERT_EQ(again.size(), features.size());
  for (std::size_t i = 0; i < features.size(); ++i) {
    EXPECT_EQ(again[i].type, features[i].type);
    EXPECT_EQ(again[i].approximate, features[i].approximate);
    EXPECT_DOUBLE_EQ(again[i].x, features[i].x);
    EXPECT_DOUBLE_EQ(again[i].top_z, features[i].top_z);
  }
}

TEST(WorkLimit, WithoutALimitNothingIsApproximate) {
  const auto program = random_strokes(30);
  fr::Options unlimited;
  unlimited.work_per_point = 0;
  const auto features = fr::recognize(program, plate(), unlimited);
  for (const auto& f : features) EXPECT_FALSE(f.approximate);
  expect_every_workingstep_once(features, program.size());
}

// Hundreds of levels of random strokes across the plate: past 128 earlier paths of its size
// around it a layer is in a crowd and coarse, with no work limit at all; the first ones are exact,
// and every workingstep is still in exactly one operation.
TEST(WorkLimit, LayersInACrowdOfOtherPathsAreCoarseWithoutALimit) {
  const auto program = random_strokes(200);
  fr::Options unlimited;
  unlimited.work_per_point = 0;
  const auto features = fr::recognize(program, plate(), unlimited);
  std::size_t approximate = 0;
  for (const auto& f : features) approximate += f.approximate ? 1 : 0;
  EXPECT_GT(approximate, 0u);
  EXPECT_FALSE(features.front().approximate);
  expect_every_workingstep_once(features, program.size());
}

TEST(WorkLimit, TheCorpusIsRecognisedWithinTheDefaultLimit) {
  for (const auto& c : ts::recognition_corpus(NCBRIDGE_SOURCE_DIR, NCBRIDGE_SHARED_DIR)) {
    for (const auto& f : ts::recognize_case(c)) EXPECT_FALSE(f.approximate) << c.name;
  }
}
