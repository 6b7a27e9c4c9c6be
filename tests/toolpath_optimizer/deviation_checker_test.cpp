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

}  // namespace
}  // namespace ncbridge::toolpath_optimizer
