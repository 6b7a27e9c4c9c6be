// Printer G-code through the optimizer: what it rewrites, what it leaves in place, and how the
// extrusion is written.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>

#include "ncbridge/toolpath_optimizer/geometry.hpp"
#include "support.hpp"

namespace ncbridge::toolpath_optimizer {
namespace {

using testing::optimize_printer_text;

// A slicer-style layer: a circle of 72 segments at radius 10 with E absolute.
std::string circle_layer(double z, double& e, int segments = 72, double r = 10, bool relative = false) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(3);
  s << "G1 Z" << z << " F7800\n";
  s << "G1 X" << 50 + r << " Y50.000\n";
  s << "G1 F1800\n";
  const double step = 2 * r * std::sin(kPi / segments);
  for (int i = 1; i <= segments; ++i) {
    const double a = 2 * kPi * i / segments;
    e += 0.0333 * step;
    s.precision(3);
    s << "G1 X" << 50 + r * std::cos(a) << " Y" << 50 + r * std::sin(a);
    s.precision(5);
    s << " E" << (relative ? 0.0333 * step : e) << "\n";
  }
  return s.str();
}

std::vector<std::string> non_motion_lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("G1 X", 0) == 0 || line.rfind("G1 Y", 0) == 0 || line.rfind("G2", 0) == 0 || line.rfind("G3", 0) == 0) continue;
    out.push_back(line);
  }
  return out;
}

TEST(PrinterOptimize, ACircleLayerBecomesOneArcWithTheSameFilament) {
  double e = 0;
  const std::string text = "G21\nG90\nM82\nG92 E0\n" + circle_layer(0.2, e);
  OptimizerOptions o;
  const auto run = optimize_printer_text(text, o);
  EXPECT_TRUE(run.deviation.passed(o.tolerance_mm)) << run.deviation.largest();
  EXPECT_EQ(run.stats.arcs, 1u);
  // The arc is written like the slicer's lines, with the last line's absolute E.
  const std::regex arc(R"(\nG3 X60 Y50 I-(9\.999\d|10) J0 E)");
  EXPECT_TRUE(std::regex_search(run.output, arc)) << run.output;
  std::ostringstream last;
  last.setf(std::ios::fixed);
  last.precision(5);
  last << " E" << e << "\n";
  EXPECT_NE(run.output.find(last.str()), std::string::npos) << run.output;
  EXPECT_EQ(non_motion_lines(run.output), non_motion_lines(text));
}

TEST(PrinterOptimize, RelativeExtrusionIsSummedExactly) {
  double e = 0;
  const std::string text = "M83\n" + circle_layer(0.2, e, 72, 10, true) + circle_layer(0.4, e, 72, 10, true);
  OptimizerOptions o;
  const auto run = optimize_printer_text(text, o);
  EXPECT_TRUE(run.deviation.passed(o.tolerance_mm));
  EXPECT_LT(run.deviation.extrusion_error, 1e-9);
  EXPECT_EQ(run.stats.arcs, 2u);
}

TEST(PrinterOptimize, NothingIsFittedAcrossARetractionAFeedChangeOrAToolChange) {
  std::string text = "G1 X0 Y0 F1800\n";
  for (int i = 1; i <= 10; ++i) text += "G1 X" + std::to_string(i) + " Y0 E" + std::to_string(i * 0.1) + "\n";
  text += "G1 E0.5 F2400\nG1 F1800\n";  // a retraction, the feed back
  for (int i = 11; i <= 20; ++i) text += "G1 X" + std::to_string(i) + " Y0 E" + std::to_string(0.5 + (i - 10) * 0.1) + "\n";
  text += "T1\n";
  for (int i = 21; i <= 30; ++i) text += "G1 X" + std::to_string(i) + " Y0 E" + std::to_string(1.5 + (i - 20) * 0.1) + "\n";
  text += "G1 X40 Y0 E2.5 F3000\nG1 X50 Y0 E3.5\n";  // the same line at another feed
  OptimizerOptions o;
  const auto run = optimize_printer_text(text, o);
  EXPECT_TRUE(run.deviation.passed(o.tolerance_mm));
  EXPECT_EQ(run.stats.lines_merged, 3u);
  EXPECT_EQ(non_motion_lines(run.output), non_motion_lines(text));
  EXPECT_NE(run.output.find("G1 X10 E1\nG1 E0.5 F2400\nG1 F1800\nG1 X20 E1.5\nT1\nG1 X30 E2.5\nG1 X40 Y0 E2.5 F3000\nG1 X50 Y0 E3.5\n"),
            std::string::npos)
      << run.output;
}

TEST(PrinterOptimize, CommentsInsideARunComeAfterTheMoveThatSpansThem) {
  const std::string text =
      "G1 X0 Y0 F1800\nG1 X1 Y0 E0.1\n;WIDTH:0.45\nG1 X2 Y0 E0.2\n\nG1 X3 Y0 E0.3\nM106 S255\nG1 X4 Y0 E0.4\n";
  OptimizerOptions o;
  const auto run = optimize_printer_text(text, o);
  EXPECT_EQ(run.output, "G1 X0 Y0 F1800\nG1 X3 E0.3\n;WIDTH:0.45\n\nM106 S255\nG1 X4 Y0 E0.4\n");
  EXPECT_TRUE(run.deviation.passed(o.tolerance_mm));
}

TEST(PrinterOptimize, CrlfFilesStayCrlf) {
  const std::string text = "G1 X0 Y0 F1800\r\nG1 X1 Y0 E0.1\r\nG1 X2 Y0 E0.2\r\nM107\r\n";
  const auto run = optimize_printer_text(text, OptimizerOptions{});
  EXPECT_EQ(run.output, "G1 X0 Y0 F1800\r\nG1 X2 E0.2\r\nM107\r\n");
}

TEST(PrinterOptimize, LinesOnlyAndMinSegment) {
  double e = 0;
  const std::string text = circle_layer(0.2, e, 360, 10);
  OptimizerOptions o;
  o.arcs = false;
  auto run = optimize_printer_text(text, o);
  EXPECT_EQ(run.stats.arcs, 0u);
  EXPECT_GT(run.stats.lines_merged, 0u);
  EXPECT_TRUE(run.deviation.passed(o.tolerance_mm));
  o.tolerance_mm = 0.005;
  run = optimize_printer_text(text, o);
  EXPECT_TRUE(run.deviation.passed(o.tolerance_mm)) << run.deviation.largest();
}

}  // namespace
}  // namespace ncbridge::toolpath_optimizer

namespace ncbridge::toolpath_optimizer {
namespace {

// A travel of G0 moves round a polygon (a slicer avoiding a printed part): on a printer G0 is a
// move at the feed in force, so with traverse arcs the run is one G2/G3 at that feed (the F in force, as the G0 lines had it), and never
// one move across the travel and the extrusion before it.
TEST(PrinterOptimize, APrinterTravelOfG0MovesBecomesAnArcWhenAsked) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(3);
  s << "G21\nG90\nM83\nG1 X60 Y50 Z0.2 F1800\nG1 X61 Y50 E0.05\nG0 F6000 X60 Y50\n";
  for (int i = 1; i <= 36; ++i) {
    const double a = kPi * i / 36;
    s << "G0 X" << 50 + 10 * std::cos(a) << " Y" << 50 + 10 * std::sin(a) << "\n";
  }
  s << "G1 X41 Y50 E0.05\n";
  OptimizerOptions o;
  auto run = optimize_printer_text(s.str(), o);
  EXPECT_EQ(run.stats.arcs, 0u) << run.output;  // G0 stays G0 unless asked
  o.traverse_arcs = true;
  run = optimize_printer_text(s.str(), o);
  EXPECT_TRUE(run.deviation.passed(o.tolerance_mm)) << run.deviation.largest();
  EXPECT_EQ(run.stats.arcs, 1u) << run.output;
  EXPECT_NE(run.output.find("\nG0 F6000 X60 Y50\nG3 X40 Y50 I-10 J0\nG1 X41 Y50 E0.05\n"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace ncbridge::toolpath_optimizer
