// Focused behaviour of the interpreter core through its public API (interpret_text): expressions,
// parameters, control flow, modal-group violations, arc errors and error locations.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/canon_printer.hpp"
#include "ncbridge/interpreter/interpreter.hpp"

namespace {

using namespace ncbridge;

struct Collector : canonical::Sink {
  std::vector<canonical::Call> calls;
  void call(const canonical::Call& c) override { calls.push_back(c); }
};

std::vector<canonical::Call> run(const std::string& program) {
  Collector sink;
  interpreter::interpret_text(program, "test.ngc", interpreter::Options{}, sink);
  return sink.calls;
}

// The calls after the start-up preamble, as rs274 prints them (without counter and N column).
std::vector<std::string> printed(const std::string& program) {
  std::vector<std::string> out;
  std::string line;
  auto calls = run(program);
  for (std::size_t i = 6; i < calls.size(); ++i) {
    interpreter::CanonPrinter::format_call(calls[i].data, line);
    out.push_back(line);
  }
  return out;
}

std::vector<canonical::Pose> traverse_ends(const std::string& program) {
  std::vector<canonical::Pose> ends;
  for (const auto& c : run(program)) {
    if (const auto* t = std::get_if<canonical::StraightTraverse>(&c.data)) ends.push_back(t->end);
  }
  return ends;
}

InputError error_of(const std::string& program) {
  try {
    run(program);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << program;
  return InputError({}, "");
}

TEST(InterpreterCore, ExpressionsFollowLinuxCncPrecedenceAndFunctions) {
  auto ends = traverse_ends(
      "G0 X[2**3**2] Y[1+2*3-4/2] Z[-7 MOD 3]\n"
      "G0 X[FIX[-2.5]] Y[FUP[-2.5]] Z[ROUND[2.5]]\n"
      "G0 X[ATAN[1]/[-1]] Y[SQRT[16]] Z[1 EQ 1.00001]\n"
      "G0 X[1 LE 0.99] Y[3 XOR 0] Z[0 OR 2]\nM2\n");
  ASSERT_EQ(ends.size(), 4u);
  EXPECT_DOUBLE_EQ(ends[0].x, 64);
  EXPECT_DOUBLE_EQ(ends[0].y, 5);
  EXPECT_DOUBLE_EQ(ends[0].z, 2);
  EXPECT_DOUBLE_EQ(ends[1].x, -3);
  EXPECT_DOUBLE_EQ(ends[1].y, -2);
  EXPECT_DOUBLE_EQ(ends[1].z, 3);
  EXPECT_DOUBLE_EQ(ends[2].x, 135);
  EXPECT_DOUBLE_EQ(ends[2].y, 4);
  EXPECT_DOUBLE_EQ(ends[2].z, 1);
  EXPECT_DOUBLE_EQ(ends[3].x, 0);
  EXPECT_DOUBLE_EQ(ends[3].y, 1);
  EXPECT_DOUBLE_EQ(ends[3].z, 1);
}

TEST(InterpreterCore, ParametersOnALineAreSetAfterItsWordsAreRead) {
  auto ends = traverse_ends("#1=5\n#1=7 G0 X#1\nG0 X#1 Y#<_x>\n#<depth>=-2 #<_g>=4\nG0 Z[#<depth>*#<_g>]\nM2\n");
  ASSERT_EQ(ends.size(), 3u);
  EXPECT_DOUBLE_EQ(ends[0].x, 5);
  EXPECT_DOUBLE_EQ(ends[1].x, 7);
  EXPECT_DOUBLE_EQ(ends[1].y, 5);
  EXPECT_DOUBLE_EQ(ends[2].z, -8);
}

TEST(InterpreterCore, LoopsConditionalsAndSubroutinesRunLikeLinuxCnc) {
  auto ends = traverse_ends(
      "o<hole> sub\n  G0 X#1 Y[#2*2]\n  o<hole> return [#1+1]\no<hole> endsub\n"
      "#1=0\no10 while [#1 LT 3]\n  o20 if [#1 EQ 1]\n    G0 Z1\n  o20 elseif [#1 EQ 2]\n    G0 Z2\n"
      "  o20 else\n    G0 Z0\n  o20 endif\n  #1=[#1+1]\no10 endwhile\n"
      "o30 repeat [2]\n  G0 A1\no30 endrepeat\n"
      "#1=9\no<hole> call [4] [5]\nG0 C#<_value> B#1\n"
      "o40 do\n  #1=[#1+1]\n  o40 if [#1 GT 10]\n    o40 break\n  o40 endif\no40 while [1]\nG0 U#1\nM2\n");
  ASSERT_EQ(ends.size(), 3u + 2u + 1u + 1u + 1u);
  EXPECT_DOUBLE_EQ(ends[0].z, 0);
  EXPECT_DOUBLE_EQ(ends[1].z, 1);
  EXPECT_DOUBLE_EQ(ends[2].z, 2);
  EXPECT_DOUBLE_EQ(ends[5].x, 4);   // the subroutine's move, with its arguments
  EXPECT_DOUBLE_EQ(ends[5].y, 10);
  EXPECT_DOUBLE_EQ(ends[6].c, 5);   // returned value
  EXPECT_DOUBLE_EQ(ends[6].b, 9);   // #1 restored after the call
  EXPECT_DOUBLE_EQ(ends[7].u, 11);  // do-while left by break
}

TEST(InterpreterCore, ModalGroupViolationsNameLineAndColumn) {
  InputError e = error_of("G21\nG0 X1 G1 Y2\nM2\n");
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 7u);
  EXPECT_NE(e.message().find("same modal group"), std::string::npos);
  InputError m = error_of("M3 M4 S100\nM2\n");
  EXPECT_EQ(m.where().column, 4u);
  InputError w = error_of("G0 X1 X2\nM2\n");
  EXPECT_NE(w.message().find("Multiple X words"), std::string::npos);
}

TEST(InterpreterCore, ArcErrorsAreReported) {
  EXPECT_NE(error_of("G1 F100\nG2 X10 Y0 I3 J0\nM2\n").message().find("Radius to end of arc differs"), std::string::npos);
  EXPECT_NE(error_of("G1 F100\nG2 X10 Y0 R2\nM2\n").message().find("too small"), std::string::npos);
  EXPECT_NE(error_of("G1 F100\nG2 X10 Y0\nM2\n").message().find("missing for arc"), std::string::npos);
  EXPECT_NE(error_of("G2 X1 I1\nM2\n").message().find("zero feed rate"), std::string::npos);
}

TEST(InterpreterCore, ExpressionErrorsPointAtTheOperator) {
  InputError e = error_of("G0 X[1/0]\nM2\n");
  EXPECT_EQ(e.where().line, 1u);
  EXPECT_EQ(e.where().column, 7u);  // the `/`
  InputError p = error_of("G0 X#<nope>\nM2\n");
  EXPECT_NE(p.message().find("#<nope>"), std::string::npos);
  EXPECT_EQ(error_of("G0 X1\n").message(), "File ended with no percent sign or program end");
}

TEST(InterpreterCore, ArcsAndCannedCyclesMatchRs274Calls) {
  auto calls = printed("G21 G17 F100\nG0 X0 Y0 Z5\nG3 X10 Y0 R-5\nG99 G81 X1 Y2 Z-1 R1 L2\nM2\n");
  std::vector<std::string> expected = {
      "SET_FEED_RATE(100.0000)", "SELECT_PLANE(CANON_PLANE_XY)", "USE_LENGTH_UNITS(CANON_UNITS_MM)",
      "STRAIGHT_TRAVERSE(0.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)",
      "ARC_FEED(10.0000, 0.0000, 5.0000, -0.0000, 1, 5.0000, 0.0000, 0.0000, 0.0000)",
      "COMMENT(\"interpreter: retract mode set to r_plane\")",
      "SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH)",
      "STRAIGHT_TRAVERSE(1.0000, 2.0000, 5.0000, 0.0000, 0.0000, 0.0000)",
      "STRAIGHT_TRAVERSE(1.0000, 2.0000, 1.0000, 0.0000, 0.0000, 0.0000)",
      "STRAIGHT_FEED(1.0000, 2.0000, -1.0000, 0.0000, 0.0000, 0.0000)",
      "STRAIGHT_TRAVERSE(1.0000, 2.0000, 1.0000, 0.0000, 0.0000, 0.0000)",
      "STRAIGHT_TRAVERSE(1.0000, 2.0000, 1.0000, 0.0000, 0.0000, 0.0000)",
      "STRAIGHT_FEED(1.0000, 2.0000, -1.0000, 0.0000, 0.0000, 0.0000)",
      "STRAIGHT_TRAVERSE(1.0000, 2.0000, 1.0000, 0.0000, 0.0000, 0.0000)",
      "SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 0.000000)", "SET_NAIVECAM_TOLERANCE(0.0000)"};
  ASSERT_GE(calls.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(calls[i], expected[i]) << "call " << i;
}

TEST(InterpreterCore, CannedCycleCallsCarryTheirHole) {
  Collector sink;
  interpreter::interpret_text("G21 F100\nG0 Z5\nG98 G83 X3 Y4 Z-2 R1 Q1 L2\nM2\n", "t.ngc", {}, sink);
  std::uint32_t last_id = 0;
  int tagged = 0;
  for (const auto& c : sink.calls) {
    if (!c.cycle) continue;
    ++tagged;
    EXPECT_EQ(c.cycle->g_code_x10, 830);
    EXPECT_FALSE(c.cycle->retract_to_r);
    EXPECT_DOUBLE_EQ(c.cycle->x, 3);
    EXPECT_DOUBLE_EQ(c.cycle->y, 4);
    EXPECT_DOUBLE_EQ(c.cycle->z, -2);
    EXPECT_DOUBLE_EQ(c.cycle->r, 1);
    EXPECT_DOUBLE_EQ(c.cycle->q, 1);
    EXPECT_EQ(c.cycle->repeat, 2u);
    last_id = c.cycle->cycle_id;
  }
  EXPECT_GT(tagged, 8);
  EXPECT_EQ(last_id, 2u);
}

// rs274 prints only the number of control points of a NURBS_FEED; the points themselves are
// checked here against the LinuxCNC rules worked by hand.
std::vector<canonical::NurbsFeed> nurbs_of(const std::string& program) {
  std::vector<canonical::NurbsFeed> out;
  for (const auto& c : run(program)) {
    if (const auto* n = std::get_if<canonical::NurbsFeed>(&c.data)) out.push_back(*n);
  }
  return out;
}

TEST(InterpreterCore, SplinesCarryTheirControlPoints) {
  using P = canonical::NurbsControlPoint;
  const auto curves = nurbs_of(
      "G21 G90 G17 F100\nG0 X1 Y2\n"
      "G5 I3 J0 P-1 Q-2 X10 Y5\n"   // cubic: start, start + IJ, end + PQ, end
      "G5 P0 Q4 X20 Y5\n"           // no IJ: the first handle mirrors the last PQ (+1, +2)
      "G5.1 I2 J-3 X30 Y0\n"        // quadratic: start, start + IJ, end
      // weights, order 4; in G91 every point is relative to where the curve starts (LinuxCNC
      // moves the current point only at G5.3)
      "G91 G5.2 X5 Y5 P2 L4\nX5 Y-5 P0.5\nX10 Y0 P1\nG5.3\n"
      "G90 G5.2 P3\nX50 Y0 P1\nX60 Y10 P1\nG5.3\nM2\n");     // P alone weighs the first point
  ASSERT_EQ(curves.size(), 5u);
  EXPECT_EQ(curves[0].order, 4);
  EXPECT_EQ(curves[0].control_points, (std::vector<P>{{1, 2, 1}, {4, 2, 1}, {9, 3, 1}, {10, 5, 1}}));
  EXPECT_EQ(curves[1].control_points, (std::vector<P>{{10, 5, 1}, {11, 7, 1}, {20, 9, 1}, {20, 5, 1}}));
  EXPECT_EQ(curves[2].order, 3);
  EXPECT_EQ(curves[2].control_points, (std::vector<P>{{20, 5, 1}, {22, 2, 1}, {30, 0, 1}}));
  EXPECT_EQ(curves[3].order, 4);
  EXPECT_EQ(curves[3].control_points, (std::vector<P>{{30, 0, 1}, {35, 5, 2}, {35, -5, 0.5}, {40, 0, 1}}));
  EXPECT_EQ(curves[4].order, 3);
  EXPECT_EQ(curves[4].control_points, (std::vector<P>{{40, 0, 3}, {50, 0, 1}, {60, 10, 1}}));
}

TEST(InterpreterCore, NurbsControlPointsNeedAPositiveWeight) {
  // rs274 takes a first G5.2 block with X and Y but no P and weighs that point -1: refused here.
  const InputError missing = error_of("G21 G17 F100\nG0 X0 Y0\nG5.2 X10 Y0 L3\nX20 Y10 P1\nX30 Y0 P1\nG5.3\nM2\n");
  EXPECT_EQ(missing.where().line, 3u);
  EXPECT_NE(std::string(missing.what()).find("positive weight P"), std::string::npos);
  const InputError zero = error_of("G21 G17 F100\nG0 X0 Y0\nG5.2 X10 Y0 P1\nX20 Y10 P0\nG5.3\nM2\n");
  EXPECT_EQ(zero.where().line, 4u);
  EXPECT_EQ(zero.where().column, 9u);
}

}  // namespace
