#include "ncbridge/bus/canonical_batcher.hpp"

#include <gtest/gtest.h>

#include "canonical_samples.hpp"

using namespace ncbridge;
using namespace ncbridge::bus;
using ncbridge::test::sample_call;
using ncbridge::test::same_call;

namespace {

struct Collected : canonical::Sink {
  std::vector<canonical::SourceFile> files;
  std::vector<canonical::Call> calls;
  void source_file(std::uint32_t i, std::string_view p) override { files.push_back({i, std::string(p)}); }
  void call(const canonical::Call& c) override { calls.push_back(c); }
};

std::vector<Envelope> run(std::size_t calls, std::size_t per_batch) {
  std::vector<Envelope> out;
  CanonicalBatcher b("job-7", per_batch, [&](const Envelope& e) { out.push_back(e); });
  b.source_file(0, "main.ngc");
  for (std::size_t i = 0; i < calls; ++i) {
    if (i == calls / 2) b.source_file(1, "sub.ngc");
    b.call(sample_call(i));
  }
  b.end();
  b.end();  // a second end() publishes nothing
  return out;
}

}  // namespace

TEST(CanonicalBatcher, PacksTheStreamIntoNumberedBatches) {
  const std::vector<Envelope> out = run(2500, 1000);
  ASSERT_EQ(out.size(), 3u);
  Collected c;
  for (std::size_t i = 0; i < out.size(); ++i) {
    EXPECT_EQ(out[i].key, "job-7");
    EXPECT_EQ(out[i].seq, i);
    EXPECT_EQ(out[i].last, i == 2);
    const canonical::DecodedBatch b = canonical::decode_batch(out[i].payload);
    EXPECT_EQ(b.seq, i);
    EXPECT_EQ(b.last, out[i].last);
    EXPECT_EQ(b.calls.size(), i < 2 ? 1000u : 500u);
    canonical::replay(b, c);
  }
  EXPECT_EQ(c.files, (std::vector<canonical::SourceFile>{{0, "main.ngc"}, {1, "sub.ngc"}}));
  ASSERT_EQ(c.calls.size(), 2500u);
  for (std::size_t i = 0; i < c.calls.size(); ++i) ASSERT_TRUE(same_call(c.calls[i], sample_call(i))) << i;
}

TEST(CanonicalBatcher, ExactMultipleEndsWithAnEmptyLastBatch) {
  const std::vector<Envelope> out = run(2000, 1000);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_TRUE(out[2].last);
  EXPECT_TRUE(canonical::decode_batch(out[2].payload).calls.empty());
  EXPECT_FALSE(out[1].last);
}

TEST(CanonicalBatcher, EmptyProgramStillEnds) {
  const std::vector<Envelope> out = run(0, 100);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].last);
  EXPECT_EQ(canonical::decode_batch(out[0].payload).files.size(), 1u);
}
