// The parts of De Backer et al. (CAD'16), generated here as a slicer writes them (many layers
// of a polygonal circle; a stadium whose straight sides are dozens of short moves), through
// `optimize --to krl --loops`: a handful of KRL commands, read back within the band.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ncbridge/toolpath_optimizer/geometry.hpp"
#include "ncbridge/toolpath_optimizer/pipeline.hpp"
#include "support.hpp"

namespace ncbridge::toolpath_optimizer {
namespace {

namespace fs = std::filesystem;

// A slicer's layer loop: Z up, travel to the start, prime, the outline, retract; absolute E.
class SlicerLike {
 public:
  SlicerLike() {
    out_.setf(std::ios::fixed);
    out_ << "; generated for ncbridge's tests, as Slic3r writes a part\nM104 S210\nG28\nG21\nG90\nM82\nG92 E0\n";
  }
  void layer(double z, const std::vector<Vec3>& outline) {
    out_.precision(3);
    out_ << "G1 Z" << z << " F7800\n";
    out_ << "G1 X" << outline[0].x << " Y" << outline[0].y << " F7800\n";
    e_ += 1;
    out_.precision(5);
    out_ << "G1 E" << e_ << " F2400\n";
    out_ << "G1 F1800\n";
    for (std::size_t i = 1; i < outline.size(); ++i) {
      e_ += 0.0333 * distance(outline[i - 1], outline[i]);
      out_.precision(3);
      out_ << "G1 X" << outline[i].x << " Y" << outline[i].y;
      out_.precision(5);
      out_ << " E" << e_ << "\n";
    }
    e_ -= 1;
    out_ << "G1 E" << e_ << " F2400\n";
  }
  std::string text() const { return out_.str() + "M104 S0\nM84\n"; }

 private:
  std::ostringstream out_;
  double e_ = 0;
};

std::vector<Vec3> circle(double r, int segments) {
  std::vector<Vec3> p;
  for (int i = 0; i <= segments; ++i) {
    const double a = 2 * kPi * i / segments;
    p.push_back({100 + r * std::cos(a), 100 + r * std::sin(a), 0});
  }
  return p;
}

// Two half circles of radius r joined by straight sides of `length`, each side cut in `pieces`.
std::vector<Vec3> stadium(double r, double length, int pieces, int arc_segments) {
  std::vector<Vec3> p;
  const double x0 = 100, y0 = 100;
  for (int i = 0; i <= pieces; ++i) p.push_back({x0 + length * i / pieces, y0 - r, 0});
  for (int i = 1; i <= arc_segments; ++i) {
    const double a = -kPi / 2 + kPi * i / arc_segments;
    p.push_back({x0 + length + r * std::cos(a), y0 + r * std::sin(a), 0});
  }
  for (int i = 1; i <= pieces; ++i) p.push_back({x0 + length - length * i / pieces, y0 + r, 0});
  for (int i = 1; i <= arc_segments; ++i) {
    const double a = kPi / 2 + kPi * i / arc_segments;
    p.push_back({x0 + r * std::cos(a), y0 + r * std::sin(a), 0});
  }
  return p;
}

struct Result {
  OptimizeResult result;
  std::string src;
};

Result optimize_to_krl(const std::string& gcode, const std::string& name) {
  const fs::path path = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()) + ".gcode");
  std::ofstream(path) << gcode;
  OptimizeRequest request;
  request.input = path;
  request.output_name = name + ".src";
  request.output = OutputFormat::Krl;
  request.loops = true;
  request.krl.name = krl_module_name(name);
  Result r;
  std::string dat;
  OutputSinks sinks;
  sinks.main = [&](std::string_view s) { r.src.append(s); };
  sinks.data = [&](std::string_view s) { dat.append(s); };
  r.result = optimize(request, sinks);
  fs::remove(path);
  return r;
}

TEST(PaperParts, ACylinderIsOneLayerOfAFewMovesInAFor) {
  SlicerLike slicer;
  for (int layer = 1; layer <= 150; ++layer) slicer.layer(0.2 * layer, circle(15, 90));
  const std::string gcode = slicer.text();
  const auto r = optimize_to_krl(gcode, "cylinder");
  std::cout << "cylinder: " << r.result.commands_in << " commands (" << r.result.motion_blocks_in
            << " motion blocks) -> " << r.result.commands_out << " KRL statements (" << r.result.motion_blocks_out
            << " motions)\n"
            << r.src;
  ASSERT_TRUE(r.result.deviation);
  EXPECT_TRUE(r.result.deviation->passed(0.025));
  EXPECT_EQ(r.result.loops.loops, 1u);
  EXPECT_NE(r.src.find("FOR NCB_LAYER = 1 TO 149\n"), std::string::npos);  // layers 2 to 150: the first starts from homing
  EXPECT_LE(r.result.motion_blocks_out, 10u);   // PTP home, first layer, the body's Z move and circle
  EXPECT_LE(r.result.commands_out, 40u);
  EXPECT_GT(r.result.motion_blocks_in, 13000u);
}

TEST(PaperParts, AStadiumKeepsOneLinePerSideAndOneArcPerEnd) {
  SlicerLike slicer;
  for (int layer = 1; layer <= 100; ++layer) slicer.layer(0.25 * layer, stadium(12, 60, 40, 36));
  const auto r = optimize_to_krl(slicer.text(), "stadium");
  std::cout << "stadium: " << r.result.commands_in << " commands -> " << r.result.commands_out << " KRL statements ("
            << r.result.motion_blocks_out << " motions)\n";
  ASSERT_TRUE(r.result.deviation);
  EXPECT_TRUE(r.result.deviation->passed(0.025));
  EXPECT_EQ(r.result.loops.loops, 1u);
  EXPECT_LE(r.result.motion_blocks_out, 16u);
  // The body: the Z move, two sides, two ends.
  const auto body_begin = r.src.find("FOR NCB_LAYER");
  const auto body = r.src.substr(body_begin, r.src.find("ENDFOR") - body_begin);
  auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (auto p = body.find(what); p != std::string::npos; p = body.find(what, p + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("CIRC "), 2u) << body;
  EXPECT_EQ(count("LIN "), 3u) << body;
}

}  // namespace
}  // namespace ncbridge::toolpath_optimizer
