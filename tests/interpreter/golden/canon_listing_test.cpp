// The golden comparison itself: what it accepts as the same listing and what it reports.
#include "support/canon_listing.hpp"

#include <gtest/gtest.h>

using ncbridge::testing::compare_canon_listings;
using ncbridge::testing::parse_canon_listing;

namespace {

const char* const kListing =
    "    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)\n"
    "    2 N10    COMMENT(\"a, comment (with) parens\")\n"
    "    3 N10    STRAIGHT_FEED(1.0000, 2.5000, -3.0000, 0.0000, 0.0000, 0.0000)\n"
    "    4 N0020  USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 50.0000, 0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000)\n"
    "    5 N..... ARC_FEED(20.0000, 0.0000, 10.0000, 0.0000, -1, -1.0000, 0.0000, 0.0000, 0.0000)\n";

bool same(const std::string& expected, const std::string& actual) {
  return compare_canon_listings(parse_canon_listing(expected), parse_canon_listing(actual)).equal;
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

}  // namespace

TEST(CanonListing, ParsesCounterNColumnNameAndArguments) {
  const auto lines = parse_canon_listing(kListing);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[1].n_column, "N10");
  EXPECT_EQ(lines[1].name, "COMMENT");
  ASSERT_EQ(lines[1].args.size(), 1u);
  EXPECT_EQ(lines[1].args[0], "\"a, comment (with) parens\"");
  EXPECT_EQ(lines[3].n_column, "N0020");
  EXPECT_EQ(lines[3].args.size(), 9u);
  EXPECT_EQ(lines[4].args[4], "-1");
}

TEST(CanonListing, EqualListingsAgreeWhateverTheSpacing) {
  EXPECT_TRUE(same(kListing, kListing));
  EXPECT_TRUE(same(kListing, with(kListing, "    3 N10    STRAIGHT", "3 N10 STRAIGHT")));
}

TEST(CanonListing, NumbersWithinTheToleranceAgree) {
  EXPECT_TRUE(same(kListing, with(kListing, "2.5000", "2.5001")));
  EXPECT_TRUE(same(kListing, with(kListing, "-3.0000", "-2.99995")));
  EXPECT_TRUE(same(kListing, with(kListing, "0.0000, -1,", "-0.0000, -1,")));
  EXPECT_FALSE(same(kListing, with(kListing, "2.5000", "2.5002")));
  EXPECT_FALSE(same(kListing, with(kListing, ", -1,", ", 1,")));
}

TEST(CanonListing, NamesNColumnsTextAndCountsMustMatch) {
  EXPECT_FALSE(same(kListing, with(kListing, "STRAIGHT_FEED", "STRAIGHT_TRAVERSE")));
  EXPECT_FALSE(same(kListing, with(kListing, "N0020 ", "N20   ")));
  EXPECT_FALSE(same(kListing, with(kListing, "with) parens", "with) paren")));
  EXPECT_FALSE(same(kListing, with(kListing, "CANON_UNITS_MM", "CANON_UNITS_INCHES")));
  EXPECT_FALSE(same(kListing, with(kListing, ", 0.0000)\n", ")\n")));
  EXPECT_FALSE(same(kListing, std::string(kListing) + "    6 N..... ON_RESET()\n"));
  EXPECT_FALSE(same(std::string(kListing) + "    6 N..... ON_RESET()\n", kListing));
  EXPECT_FALSE(same(kListing, with(kListing, "    5 N.....", "garbage")));
}

TEST(CanonListing, ReportShowsTheFirstDifferenceWithContext) {
  const auto result = compare_canon_listings(parse_canon_listing(kListing),
                                             parse_canon_listing(with(kListing, "2.5000", "9.5000")));
  ASSERT_FALSE(result.equal);
  EXPECT_NE(result.report.find("first difference at call 3"), std::string::npos) << result.report;
  EXPECT_NE(result.report.find("> " "    3 N10    STRAIGHT_FEED(1.0000, 9.5000"), std::string::npos) << result.report;
  EXPECT_NE(result.report.find("USE_LENGTH_UNITS"), std::string::npos) << result.report;
}
