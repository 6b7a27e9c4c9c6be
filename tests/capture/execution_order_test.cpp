#include <gtest/gtest.h>

#include "ncbridge/capture/execution_order.hpp"
#include "ncbridge/common/error.hpp"

using ncbridge::capture::ExecutedLine;
using ncbridge::capture::execution_order;

namespace {

std::vector<std::uint32_t> lines_of(const std::vector<ExecutedLine>& order) {
  std::vector<std::uint32_t> out;
  for (const auto& e : order) out.push_back(e.line);
  return out;
}

}  // namespace

TEST(ExecutionOrder, LoopsRunOncePerPassAndCallsBecomeParameterSettings) {
  const std::string program =
      "G21 G90\n"                     // 1
      "o100 sub\n"                    // 2
      "  G1 X#1 F100\n"               // 3
      "o100 endsub\n"                 // 4
      "#2 = 0\n"                      // 5
      "o200 while [#2 LT 2]\n"        // 6
      "  G0 Y#2\n"                    // 7
      "  #2 = [#2 + 1]\n"             // 8
      "o200 endwhile\n"               // 9
      "o100 call [5]\n"               // 10
      "M2\n";                         // 11
  const auto order = execution_order("p.ngc", program, {});
  EXPECT_EQ(lines_of(order), (std::vector<std::uint32_t>{1, 5, 7, 8, 7, 8, 10, 3, 11}));
  EXPECT_EQ(order[6].text, "#1=[5]");
  EXPECT_FALSE(order[0].moves);
  EXPECT_TRUE(order[2].moves);   // G0 Y#2
  EXPECT_FALSE(order[3].moves);  // #2 = ...
  EXPECT_TRUE(order[7].moves);   // G1 X#1 in the subroutine
}

TEST(ExecutionOrder, OtherDialectsAreTheirLinesAsWritten) {
  const auto order = execution_order("p.nc", "%\nO1\nG0 X1\n\nM30\n%\n", {}, ncbridge::interpreter::Dialect::Fanuc);
  EXPECT_EQ(lines_of(order), (std::vector<std::uint32_t>{1, 2, 3, 5, 6}));
}

TEST(ExecutionOrder, AnErrorNamesTheProgramsOwnLine) {
  try {
    execution_order("bad.ngc", "G21\nG0 X0\nG1 X1 Q\n", {});
    FAIL() << "no error";
  } catch (const ncbridge::InputError& e) {
    EXPECT_EQ(e.where().file, "bad.ngc");
    EXPECT_EQ(e.where().line, 3u) << e.what();
  }
}
