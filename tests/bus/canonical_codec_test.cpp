#include "ncbridge/canonical/proto_codec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "canonical_samples.hpp"
#include "ncbridge/common/error.hpp"

using namespace ncbridge;
using namespace ncbridge::canonical;
using ncbridge::test::sample_call;
using ncbridge::test::same_call;

namespace {

constexpr std::size_t kAlternatives = std::variant_size_v<Data>;

std::vector<Call> sample_calls(std::size_t n) {
  std::vector<Call> calls;
  calls.reserve(n);
  for (std::size_t i = 0; i < n; ++i) calls.push_back(sample_call(i));
  return calls;
}

class Collector : public Sink {
 public:
  std::vector<SourceFile> files;
  std::vector<Call> calls;
  void source_file(std::uint32_t index, std::string_view path) override { files.push_back({index, std::string(path)}); }
  void call(const Call& c) override { calls.push_back(c); }
};

}  // namespace

TEST(CanonicalCodec, SampleCallsDifferInEveryAlternative) {
  // Guards the helper itself: equal-looking samples would make the round trips below vacuous.
  const Call a = sample_call(5);
  Call b = a;
  EXPECT_TRUE(same_call(a, b));
  b.source.line += 1;
  EXPECT_FALSE(same_call(a, b));
  Call arc = sample_call(17);
  ASSERT_TRUE(std::holds_alternative<ArcFeed>(arc.data));
  Call arc2 = arc;
  std::get<ArcFeed>(arc2.data).w = -std::get<ArcFeed>(arc2.data).w;
  EXPECT_FALSE(same_call(arc, arc2));
  Call tag = sample_call(1);
  Call tag2 = tag;
  tag2.cycle->repeat += 1;
  EXPECT_FALSE(same_call(tag, tag2));
}

TEST(CanonicalCodec, EveryCallTypeRoundTrips) {
  // Each alternative twice: once plain, once tagged by a canned cycle.
  const std::vector<Call> calls = sample_calls(2 * kAlternatives);
  const std::vector<SourceFile> files{{0, "part.ngc"}, {1, "/tmp/sub \xe9t\xe9.ngc"}};
  const std::string bytes = encode_batch({"job-1", 7, files, calls, true});
  const DecodedBatch back = decode_batch(bytes);
  EXPECT_EQ(back.job_id, "job-1");
  EXPECT_EQ(back.seq, 7u);
  EXPECT_TRUE(back.last);
  EXPECT_EQ(back.files, files);
  ASSERT_EQ(back.calls.size(), calls.size());
  std::vector<bool> seen(kAlternatives, false);
  for (std::size_t i = 0; i < calls.size(); ++i) {
    EXPECT_TRUE(same_call(calls[i], back.calls[i])) << "call " << i << ": " << name_of(calls[i].data);
    seen[back.calls[i].data.index()] = true;
  }
  for (std::size_t k = 0; k < kAlternatives; ++k) EXPECT_TRUE(seen[k]) << "alternative " << k;
}

TEST(CanonicalCodec, DoublesKeepTheirBits) {
  const double values[] = {-0.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(), 0.1, -1e-300, 0.0};
  std::vector<Call> calls;
  for (double v : values) calls.push_back({StraightFeed{{v, -v, v, v, v, v, v, v, v}}, {0, 1, 0}, std::nullopt});
  const DecodedBatch back = decode_batch(encode_batch({"j", 0, {}, calls, false}));
  ASSERT_EQ(back.calls.size(), calls.size());
  for (std::size_t i = 0; i < calls.size(); ++i) EXPECT_TRUE(same_call(calls[i], back.calls[i])) << values[i];
  EXPECT_TRUE(std::signbit(std::get<StraightFeed>(back.calls[0].data).end.x));
  EXPECT_EQ(back.calls[0].source.n_number, 0);  // N0 is a real N word, not "none"
}

TEST(CanonicalCodec, EmptyLastBatch) {
  const DecodedBatch back = decode_batch(encode_batch({"job", 12, {}, {}, true}));
  EXPECT_TRUE(back.last);
  EXPECT_EQ(back.seq, 12u);
  EXPECT_TRUE(back.calls.empty());
}

TEST(CanonicalCodec, HundredThousandCallProgramInBatches) {
  const std::vector<Call> calls = sample_calls(100'000);
  const std::vector<SourceFile> files{{0, "big.ngc"}};
  constexpr std::size_t batch_size = 1024;
  Collector collector;
  std::uint64_t seq = 0;
  std::size_t bytes_total = 0;
  for (std::size_t at = 0; at < calls.size(); at += batch_size, ++seq) {
    const std::size_t n = std::min(batch_size, calls.size() - at);
    const bool last = at + n == calls.size();
    const std::string bytes = encode_batch(
        {"big", seq, seq == 0 ? std::span<const SourceFile>(files) : std::span<const SourceFile>(),
         std::span<const Call>(calls).subspan(at, n), last});
    bytes_total += bytes.size();
    const DecodedBatch back = decode_batch(bytes);
    EXPECT_EQ(back.seq, seq);
    EXPECT_EQ(back.last, last);
    replay(back, collector);
  }
  EXPECT_EQ(seq, (calls.size() + batch_size - 1) / batch_size);
  EXPECT_EQ(collector.files, files);
  ASSERT_EQ(collector.calls.size(), calls.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < calls.size(); ++i) differing += same_call(calls[i], collector.calls[i]) ? 0 : 1;
  EXPECT_EQ(differing, 0u);
  EXPECT_LT(bytes_total, calls.size() * 200);  // about 100 bytes a call on this sample
}

TEST(CanonicalCodec, HundredThousandCallsInOneBatch) {
  const std::vector<Call> calls = sample_calls(100'000);
  const DecodedBatch back = decode_batch(encode_batch({"one", 0, {}, calls, true}));
  ASSERT_EQ(back.calls.size(), calls.size());
  EXPECT_TRUE(same_call(calls.front(), back.calls.front()));
  EXPECT_TRUE(same_call(calls.back(), back.calls.back()));
}

TEST(CanonicalCodec, EveryTruncationIsRejected) {
  const std::vector<Call> calls = sample_calls(kAlternatives);
  const std::string bytes = encode_batch({"job", 3, {}, calls, false});
  ASSERT_GT(bytes.size(), 100u);
  for (std::size_t cut = 0; cut < bytes.size(); ++cut) {
    EXPECT_THROW(decode_batch(std::string_view(bytes).substr(0, cut)), InputError) << "cut at " << cut;
  }
}

TEST(CanonicalCodec, RandomBytesAreRejectedCleanly) {
  std::mt19937 rng(20240521);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<int> length(0, 300);
  int rejected = 0;
  for (int round = 0; round < 2000; ++round) {
    std::string junk(static_cast<std::size_t>(length(rng)), '\0');
    for (char& c : junk) c = static_cast<char>(byte(rng));
    try {
      decode_batch(junk);
    } catch (const InputError& e) {
      ++rejected;
      EXPECT_EQ(e.where().file, "<canonical batch>");
    }
  }
  EXPECT_GE(rejected, 1990);  // a random string is almost never a well-formed, counted batch
}

TEST(CanonicalCodec, FlippedBytesNeverCrash) {
  const std::vector<Call> calls = sample_calls(kAlternatives);
  const std::string bytes = encode_batch({"job", 3, {}, calls, false});
  std::mt19937 rng(7);
  int rejected = 0;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    std::string bad = bytes;
    bad[i] = static_cast<char>(bad[i] ^ static_cast<char>(1 + rng() % 255));
    try {
      const DecodedBatch b = decode_batch(bad);
      EXPECT_LE(b.calls.size(), calls.size() + 1);
    } catch (const InputError&) {
      ++rejected;
    }
  }
  EXPECT_GT(rejected, 0);
}

TEST(CanonicalCodec, CallWithoutDataIsRejected) {
  // calls (field 4) = one empty Call; call_count (field 15) = 1.
  const std::string bytes("\x22\x00\x78\x01", 4);
  try {
    decode_batch(bytes);
    FAIL() << "accepted a call with no canonical function";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("call 0"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("no canonical function"), std::string::npos) << e.message();
  }
}

TEST(CanonicalCodec, EnumOutOfRangeIsRejected) {
  // calls = { use_length_units (field 10) { units = 7 } }, call_count = 1.
  const std::string bytes("\x22\x04\x52\x02\x08\x07\x78\x01", 8);
  try {
    decode_batch(bytes);
    FAIL() << "accepted units = 7";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("units out of range: 7"), std::string::npos) << e.message();
  }
  // The same with units = 1 (millimetres) is a good batch.
  const DecodedBatch ok = decode_batch(std::string("\x22\x04\x52\x02\x08\x01\x78\x01", 8));
  ASSERT_EQ(ok.calls.size(), 1u);
  EXPECT_EQ(std::get<UseLengthUnits>(ok.calls[0].data).units, Units::Millimeters);
}

TEST(CanonicalCodec, WrongCallCountIsRejected) {
  // One good call, but call_count says 2.
  EXPECT_THROW(decode_batch(std::string("\x22\x04\x52\x02\x08\x01\x78\x02", 8)), InputError);
  EXPECT_THROW(decode_batch(std::string()), InputError);
}
