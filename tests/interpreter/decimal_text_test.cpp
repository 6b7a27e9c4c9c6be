// The interpreter's fast decimal reading and %.4f printing must give exactly what the C library
// gives (strtod, printf), including ties, negative zero and numbers the fast paths hand over.
#include "decimal_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

namespace ncbridge::interpreter {
namespace {

std::string printf_fixed(double v, int precision) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%.*f", precision, v);
  return buf;
}

std::string ours_fixed(double v, int precision) {
  std::string s;
  append_fixed(s, v, precision);
  return s;
}

TEST(AppendFixed, MatchesPrintfOnChosenValues) {
  const double values[] = {0.0, -0.0, 1.0, -1.0, 0.00005, -0.00005, 0.00004999, 1.03125, 2.00015,
                           0.12345, 123.45675, 1e-9, -1e-9, 999999999.99995, 1e9, 1e15, -2.5e20,
                           25.4, 1.0 / 3.0, 2.0 / 3.0, 0.30000000000000004, 4503599627370496.5,
                           150.494, -16.5587, 6.28318530717958647692};
  for (double v : values) {
    EXPECT_EQ(ours_fixed(v, 4), printf_fixed(v, 4)) << v;
    EXPECT_EQ(ours_fixed(v, 6), printf_fixed(v, 6)) << v;
  }
}

TEST(AppendFixed, MatchesPrintfOnTiesAndRandomValues) {
  std::mt19937_64 random(20260101);
  std::uniform_real_distribution<double> coordinate(-2000.0, 2000.0);
  std::uniform_int_distribution<int> exponent(-30, 40);
  int checked = 0;
  for (int i = 0; i < 200000; ++i) {
    double v = coordinate(random);
    if (i % 4 == 1) v = std::ldexp(std::floor(v * 64.0), -7);            // binary fractions: exact ties
    if (i % 4 == 2) v = std::round(v * 1e5) / 1e5;                        // 5-decimal text values
    if (i % 4 == 3) v = std::ldexp(coordinate(random), exponent(random));  // any magnitude
    ASSERT_EQ(ours_fixed(v, 4), printf_fixed(v, 4)) << v;
    ++checked;
  }
  EXPECT_EQ(checked, 200000);
}

double strtod_of(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

TEST(ParseDecimal, MatchesStrtod) {
  const char* texts[] = {"0", "-0", "1", "-1", ".5", "-.5", "5.", "0.005", "150.494", "-16.5587",
                         "000123.4500", "9007199254740993", "12345678901234567890123",
                         "0.1234567890123456789012345", "1.7976931348623157", "3.14159265358979323846"};
  for (const char* t : texts) {
    const std::string text(t);
    double v = 99;
    ASSERT_TRUE(parse_decimal(text.data(), text.data() + text.size(), v)) << text;
    const double want = strtod_of(text);
    EXPECT_EQ(v, want) << text;
    EXPECT_EQ(std::signbit(v), std::signbit(want)) << text;
  }
  std::mt19937_64 random(7);
  std::uniform_int_distribution<std::uint64_t> digits(0, 99999999999ULL);
  std::uniform_int_distribution<int> point(0, 12);
  for (int i = 0; i < 100000; ++i) {
    std::string text = std::to_string(digits(random));
    const auto at = static_cast<std::size_t>(point(random));
    if (at < text.size()) text.insert(text.size() - at, ".");
    if (i % 2) text.insert(0, "-");
    double v = 0;
    ASSERT_TRUE(parse_decimal(text.data(), text.data() + text.size(), v)) << text;
    ASSERT_EQ(v, strtod_of(text)) << text;
  }
}

TEST(ParseDecimal, RejectsWhatIsNotADecimal) {
  for (const std::string text : {"", "-", ".", "1.2.3", "1e5", "+1", "1 2", "x"}) {
    double v = 0;
    EXPECT_FALSE(parse_decimal(text.data(), text.data() + text.size(), v)) << text;
  }
}

}  // namespace
}  // namespace ncbridge::interpreter
