// CNC programs through the interpreter into the optimizer's elements, and back to calls.
#include <gtest/gtest.h>

#include <cmath>

#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/canon_printer.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/toolpath_optimizer/canonical_bridge.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"

namespace ncbridge::toolpath_optimizer {
namespace {

std::vector<Element> elements(const std::string& program, interpreter::Dialect dialect = interpreter::Dialect::Rs274Ngc) {
  ElementCollector collector;
  CanonicalFrontEnd front_end(collector);
  interpreter::Options options;
  options.dialect = dialect;
  options.require_program_end = false;
  std::vector<setup::Tool> tools(1);
  tools[0].number = tools[0].pocket = 1;
  tools[0].length = 50;
  options.tools = setup::ToolList(tools);
  interpreter::interpret_text(program, "t.ngc", options, front_end);
  return collector.elements;
}

std::vector<Motion> motions(const std::vector<Element>& e) {
  std::vector<Motion> out;
  for (const auto& x : e) {
    if (const auto* m = std::get_if<Motion>(&x.item)) out.push_back(*m);
  }
  return out;
}

TEST(CncFrontEnd, MotionsFeedsPlanesAndWhatIsKept) {
  const auto e = elements(
      "G21 G90 G17 F600\nG0 X0 Y0 Z5\nG1 Z-1\nG1 X10\nG18 G2 X20 Z-1 I5 K0\nG19 G91 G1 Y5 Z1\n"
      "G90 G17 G81 X30 Y0 Z-5 R2 F100\nG80\nG93 G1 X40 F2\n");
  const auto m = motions(e);
  ASSERT_GE(m.size(), 7u);
  EXPECT_FALSE(m[0].start_known);  // the machine's start is not in the stream
  EXPECT_EQ(m[0].kind, MotionKind::Traverse);
  EXPECT_TRUE(m[1].start_known);
  EXPECT_DOUBLE_EQ(m[2].feed, 600);
  EXPECT_EQ(m[3].kind, MotionKind::Arc);
  EXPECT_EQ(m[3].arc.plane, canonical::Plane::XZ);
  EXPECT_TRUE(m[3].keep);
  EXPECT_EQ(m[4].arc.plane, canonical::Plane::YZ);
  EXPECT_DOUBLE_EQ(m[4].end.y, 5);  // G91 resolved by the interpreter
  bool cycle_kept = false;
  double inverse_time_feed = 0;
  for (const auto& x : m) {
    if (x.end.x == 30 && x.keep) cycle_kept = true;
    if (x.end.x == 40) inverse_time_feed = x.feed;
  }
  EXPECT_TRUE(cycle_kept);
  // G93: the interpreter hands each block's feed over in units/min (a feed call per block, which
  // ends any run), as LinuxCNC does.
  EXPECT_NEAR(inverse_time_feed, 10.0 * 2, 1e-9);  // 10 mm in 1/2 min
}

TEST(CncFrontEnd, AWorkOffsetChangeMovesTheProgramPositionNotTheMachine) {
  const auto m = motions(elements("G21 G90 G10 L2 P2 X100\nG54 G0 X0 Y0 Z0\nG55\nG1 X10 F100\n"));
  ASSERT_EQ(m.size(), 2u);
  // After G55 (X offset 100) the machine is at program X -100.
  EXPECT_DOUBLE_EQ(m[1].start.x, -100);
  EXPECT_DOUBLE_EQ(m[1].end.x, 10);
}

TEST(CncFrontEnd, BackToCallsAsTheyCame) {
  const std::string program = "G21 G90 F500\nG0 X1 Y2 Z3\nG1 X5\nG2 X9 Y2 I2 J0\nG3 X5 Y2 I-2 J0 P2\nM2\n";
  std::string direct, through;
  struct Printer final : canonical::Sink {
    std::string* out;
    void call(const canonical::Call& c) override {
      std::string text;
      interpreter::CanonPrinter::format_call(c.data, text);
      *out += text + "\n";
    }
  } a, b;
  a.out = &direct;
  b.out = &through;
  interpreter::Options options;
  interpreter::interpret_text(program, "t.ngc", options, a);
  for (const auto& e : elements(program)) to_canonical(e, b);
  EXPECT_EQ(through, direct);
}

TEST(CncFrontEnd, FanucReadsSmallArcsItsControlAccepts) {
  // An HSM post's arc of radius 0.0125 in whose end radius is 0.0001 in shorter (0.8 %):
  // LinuxCNC refuses more than 0.1 %, Fanuc only looks at the absolute difference (parameter
  // 3410), so the Fanuc front-end reads it and RS274/NGC still refuses it.
  const std::string fanuc = "O1001\nG20 G90 G17\nG0 X1.0503 Y-0.008 Z0\nG1 F40. X1.0503\nG2 X1.0254 Y-0.008 I-0.0125 J0.\nM30\n";
  EXPECT_NO_THROW(elements(fanuc, interpreter::Dialect::Fanuc));
  const std::string ngc = "G20 G90 G17\nG0 X1.0503 Y-0.008 Z0\nG1 F40. X1.0503\nG2 X1.0254 Y-0.008 I-0.0125 J0.\nM2\n";
  EXPECT_THROW(elements(ngc), InputError);
}

}  // namespace
}  // namespace ncbridge::toolpath_optimizer
