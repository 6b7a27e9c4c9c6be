// The deviation checker finds what it should: a path moved out of the band, a missing or extra
// vertex, extrusion moved between segments, a lost retraction.
#include <gtest/gtest.h>

#include "support.hpp"

namespace ncbridge::toolpath_optimizer {
namespace {

using testing::printer_path;

const std::string kInput =
    "G1 X0 Y0 F1800\n"
    "G1 X10 Y0 E1\n"
    "G1 X20 Y0 E2\n"
    "G1 E1\n"
    "G1 X20 Y10 E3\n";

DeviationReport check(const std::string& output, double tol = 0.025) {
  DeviationOptions o;
  o.tolerance = tol;
  return check_deviation(printer_path(kInput), printer_path(output), o);
}

TEST(DeviationChecker, TheSameProgramIsWithinAnyBand) {
  const auto d = check(kInput, 0.001);
  EXPECT_TRUE(d.passed(0.001));
  EXPECT_EQ(d.largest(), 0);
  EXPECT_EQ(d.spans, 3u);
}

TEST(DeviationChecker, AMergedLineIsOneSpan) {
  const auto d = check("G1 X0 Y0 F1800\nG1 X20 Y0 E2\nG1 E1\nG1 X20 Y10 E3\n");
  EXPECT_TRUE(d.passed(0.025)) << (d.problems.empty() ? "" : d.problems.front());
  EXPECT_EQ(d.spans, 2u);
}

TEST(DeviationChecker, AnArcThatBulgesTooFarFails) {
  // From (0,0) to (20,0) through a circle of radius 100: it bulges 0.5 mm off the input line.
  const auto d = check("G1 X0 Y0 F1800\nG2 X20 Y0 I10 J-99.4987 E2\nG1 E1\nG1 X20 Y10 E3\n");
  EXPECT_FALSE(d.passed(0.025));
  EXPECT_NEAR(d.output_to_input, 0.5013, 1e-3);
  // A radius of 2000 mm bulges 0.025 mm: inside a 0.03 band, outside 0.02.
  const std::string flat = "G1 X0 Y0 F1800\nG2 X20 Y0 I10 J-1999.975 E2\nG1 E1\nG1 X20 Y10 E3\n";
  EXPECT_TRUE(check(flat, 0.03).passed(0.03));
  EXPECT_FALSE(check(flat, 0.02).passed(0.02));
}

TEST(DeviationChecker, AnInputVertexLeftOutOfTheBandFails) {
  // The input bends by 0.03 mm at X10; the output goes straight.
  const std::string input = "G1 X0 Y0 F1800\nG1 X10 Y0.03 E1\nG1 X20 Y0 E2\n";
  const std::string output = "G1 X0 Y0 F1800\nG1 X20 Y0 E2\n";
  DeviationOptions o;
  o.tolerance = 0.025;
  auto d = check_deviation(printer_path(input), printer_path(output), o);
  EXPECT_FALSE(d.passed(0.025));
  EXPECT_NEAR(d.input_to_output, 0.03, 1e-9);
  o.tolerance = 0.031;
  d = check_deviation(printer_path(input), printer_path(output), o);
  EXPECT_TRUE(d.passed(0.031));
  // An output vertex that is no input vertex is a mismatch, whatever the band.
  EXPECT_FALSE(check("G1 X0 Y0 F1800\nG1 X10 Y0.001 E1\nG1 X20 Y0 E2\nG1 E1\nG1 X20 Y10 E3\n", 1).passed(1));
}

TEST(DeviationChecker, ExtrusionMovedBetweenSegmentsFails) {
  const auto d = check("G1 X0 Y0 F1800\nG1 X10 Y0 E1.5\nG1 X20 Y0 E2\nG1 E1\nG1 X20 Y10 E3\n");
  EXPECT_FALSE(d.passed(0.025));
  EXPECT_NEAR(d.extrusion_error, 0.5, 1e-9);
}

TEST(DeviationChecker, ALostRetractionOrAnEndNotOnTheInputFails) {
  EXPECT_FALSE(check("G1 X0 Y0 F1800\nG1 X20 Y0 E2\nG1 X20 Y10 E3\n").passed(0.025));
  EXPECT_FALSE(check("G1 X0 Y0 F1800\nG1 X15 Y0 E1.5\nG1 X20 Y0 E2\nG1 E1\nG1 X20 Y10 E3\n").passed(0.025));
  EXPECT_FALSE(check("G1 X0 Y0 F1800\nG1 X10 Y0 E1\nG1 X20 Y0 E2\nG1 E1\n").passed(0.025));  // stops short
}

// Fed as a pipeline feeds it (each output piece soon after the input it stands for), the checker
// finds what it finds given both paths whole, and holds a few pieces, not the path.
TEST(DeviationChecker, StreamingHoldsOnlyWhatTheOutputHasNotCaughtUpWith) {
  std::string input = "G1 X0 Y0 F1800\n", output = input;
  double e = 0;
  for (int i = 1; i <= 3000; ++i) {
    // Zigzag pairs of collinear moves; the output merges each pair.
    const double y = (i / 2) % 2 ? 5 : 0;
    e += 0.5;
    input += "G1 X" + std::to_string(i) + " Y" + std::to_string(y * (i % 2 ? 0.5 : 1)) + " E" + std::to_string(e) + "\n";
    if (i % 2 == 0) output += "G1 X" + std::to_string(i) + " Y" + std::to_string(y) + " E" + std::to_string(e) + "\n";
  }
  const auto in = testing::printer_path(input), out = testing::printer_path(output);
  DeviationOptions o;
  o.tolerance = 2.6;
  const DeviationReport whole = check_deviation(in, out, o);
  DeviationChecker streaming(o);
  std::size_t j = 0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    streaming.input(in[i]);
    if (i % 2 == 1) streaming.output(out[j++]);
  }
  while (j < out.size()) streaming.output(out[j++]);
  const DeviationReport streamed = streaming.finish();
  EXPECT_TRUE(whole.passed(o.tolerance)) << (whole.problems.empty() ? "" : whole.problems.front());
  EXPECT_EQ(streamed.spans, whole.spans);
  EXPECT_EQ(streamed.largest(), whole.largest());
  EXPECT_EQ(streamed.problem_count, whole.problem_count);
  EXPECT_EQ(streamed.layer_count, whole.layer_count);
  EXPECT_LE(streaming.most_held(), 4u);
  // An output that leaves the input is found the same way streaming.
  DeviationChecker wrong(o);
  for (const auto& p : in) wrong.input(p);
  auto bad = out;
  bad[700].end.y += 1;
  for (const auto& p : bad) wrong.output(p);
  const DeviationReport r = wrong.finish();
  EXPECT_FALSE(r.passed(o.tolerance));
  EXPECT_EQ(r.problems, check_deviation(in, bad, o).problems);
}

}  // namespace
}  // namespace ncbridge::toolpath_optimizer
