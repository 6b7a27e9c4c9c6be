// The CC1 adapter: canonical calls -> cc1_builder's CC1 model -> recogniser input -> features,
// on the paper's programs (the same recognition as from the canonical stream directly).
#include <gtest/gtest.h>

#include "canon_text_reader.hpp"
#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/feature_recognizer/cc1_input.hpp"
#include "ncbridge/feature_recognizer/recognizer.hpp"
#include "ncbridge/feature_recognizer/scoring.hpp"
#include "ncbridge/setup/stock.hpp"
#include "recognition_corpus.hpp"

namespace fr = ncbridge::feature_recognizer;
namespace ts = ncbridge::test_support;

class Cc1Input : public testing::TestWithParam<std::string> {};

TEST_P(Cc1Input, RecognisesFromTheCc1ModelAsFromTheCanonicalStream) {
  ts::RecognitionCase c;
  for (const auto& each : ts::recognition_corpus(NCBRIDGE_SOURCE_DIR, NCBRIDGE_SHARED_DIR)) {
    if (each.name == GetParam()) c = each;
  }
  ASSERT_FALSE(c.name.empty());
  ncbridge::cc1_builder::Options options;
  options.tools = ncbridge::setup::read_tool_list(c.tools);
  options.stock = ncbridge::setup::read_stock(c.stock);
  const auto project = ncbridge::cc1_builder::build_cc1(ts::read_canon_text(c.canon), options);
  const auto workingsteps = fr::workingsteps_from_cc1(project);
  ASSERT_FALSE(workingsteps.empty());
  const auto stock = fr::stock_from_cc1(project).value_or(*options.stock);
  const auto features = fr::recognize(workingsteps, stock);
  const auto s = fr::score(features, fr::read_truth(c.truth, c.truth_program));
  EXPECT_EQ(s.overall.matched, s.overall.truth);
  EXPECT_EQ(s.overall.recognized, s.overall.truth);
  // Operation workingstep indices point into the adapter's list.
  for (const auto& f : features) {
    for (const auto& op : f.operations) {
      for (auto w : op.workingsteps) EXPECT_LT(w, workingsteps.size());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Programs, Cc1Input,
                         testing::Values("paper_face_mill", "paper_test_part", "p01_block_reference", "p05_slots"));
