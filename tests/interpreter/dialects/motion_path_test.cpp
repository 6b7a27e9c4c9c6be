// The tool-path comparison the dialect tests rely on must be able to fail.
#include <gtest/gtest.h>

#include "motion_path.hpp"

using ncbridge::testing::compare_tool_paths;
using ncbridge::testing::tool_path;

TEST(ToolPath, DropsZeroLengthMovesAndKeepsArcs) {
  const char* listing =
      "    1 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)\n"
      "    2 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)\n"
      "    3 N..... SET_FEED_RATE(100.0000)\n"
      "    4 N..... STRAIGHT_FEED(0.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)\n"
      "    5 N..... ARC_FEED(10.0000, 0.0000, 5.0000, 0.0000, 1, 5.0000, 0.0000, 0.0000, 0.0000)\n";
  auto path = tool_path(listing);
  ASSERT_EQ(path.size(), 2u);
  EXPECT_EQ(path[0].name, "STRAIGHT_TRAVERSE");
  EXPECT_EQ(path[1].name, "ARC_FEED");
}

TEST(ToolPath, ReportsTheFirstDifferenceBeyondTolerance) {
  auto a = tool_path("    1 N..... STRAIGHT_FEED(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)\n");
  auto b = tool_path("    1 N..... STRAIGHT_FEED(1.0000, 2.0200, 3.0000, 0.0000, 0.0000, 0.0000)\n");
  auto c = tool_path("    1 N..... STRAIGHT_FEED(1.0050, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)\n");
  EXPECT_FALSE(compare_tool_paths(a, b, 0.01).equal);
  EXPECT_TRUE(compare_tool_paths(a, c, 0.01).equal);
  auto d = tool_path("    1 N..... STRAIGHT_TRAVERSE(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)\n");
  EXPECT_FALSE(compare_tool_paths(a, d, 0.01).equal);  // a rapid is not a feed
  EXPECT_FALSE(compare_tool_paths(a, {}, 0.01).equal);
}
