#include "milling_program_generator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ncbridge::bench {
namespace {

constexpr double kCell = 60;          // mm, one pocket and two holes per cell
constexpr double kFaceTool = 50, kMillTool = 10, kDrill = 8;
constexpr int kPocketLayers = 2, kLoops = 3;
constexpr int kLinesPerCell = 1 + kPocketLayers * (3 + kLoops * 5 + 1) + 2;  // pocket, holes

void line(std::string& out, const char* format, double a = 0, double b = 0, double c = 0) {
  char buf[128];
  std::snprintf(buf, sizeof buf, format, a, b, c);
  out += buf;
  out += '\n';
}

}  // namespace

MillingProgram generate_milling_program(long lines) {
  // Cells in a square-ish grid; the face passes add about one line per 10 mm of width.
  const int cells = std::max(1, static_cast<int>(lines / (kLinesPerCell + 1)));
  const int columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(cells)))));
  const int rows = (cells + columns - 1) / columns;
  const double width = columns * kCell, height = rows * kCell;
  MillingProgram p;
  p.cells = cells;
  std::string& out = p.program;
  out.reserve(static_cast<std::size_t>(lines) * 24);
  out += "G21 G90 G17 G40 G49 G54\n";
  // Face the top (Z 1 -> 0) bidirectionally along Y.
  out += "T1 M6\nG43 H1\nS1500 M3\n";
  const double step = 0.8 * kFaceTool;
  line(out, "G0 X%.3f Y%.3f Z20", 0, -kFaceTool / 2 - 5);
  line(out, "G1 Z0 F300");
  bool up = true;
  for (double x = 0; x <= width + 1e-9; x += step) {
    line(out, "G1 X%.3f F1200", x);
    line(out, "Y%.3f", up ? height + kFaceTool / 2 + 5 : -kFaceTool / 2 - 5);
    up = !up;
  }
  out += "G0 Z20\n";
  // Pockets: 30 x 20, 6 deep in two layers, three contour-parallel loops per layer.
  out += "T2 M6\nG43 H2\nS8000 M3\n";
  for (int c = 0; c < cells; ++c) {
    const double cx = (c % columns + 0.5) * kCell, cy = (c / columns + 0.5) * kCell - 10;
    line(out, "G0 X%.3f Y%.3f Z5", cx, cy);
    for (int layer = 1; layer <= kPocketLayers; ++layer) {
      line(out, "G0 Z%.3f", 1.0 - 3 * (layer - 1));
      line(out, "G1 Z%.3f F300", -3.0 * layer);
      line(out, "G1 X%.3f Y%.3f F900", cx, cy);
      for (int loop = 1; loop <= kLoops; ++loop) {
        const double hx = (15 - kMillTool / 2) * loop / kLoops, hy = (10 - kMillTool / 2) * loop / kLoops;
        line(out, "G1 X%.3f Y%.3f", cx + hx, cy - hy);
        line(out, "Y%.3f", cy + hy);
        line(out, "X%.3f", cx - hx);
        line(out, "Y%.3f", cy - hy);
        line(out, "X%.3f", cx + hx);
      }
      line(out, "G0 Z5");
    }
  }
  out += "G0 Z20\n";
  // Two holes per cell, 15 deep.
  out += "T3 M6\nG43 H3\nS2000 M3\n";
  for (int c = 0; c < cells; ++c) {
    const double cx = (c % columns + 0.5) * kCell, cy = (c / columns + 0.5) * kCell + 18;
    line(out, "G81 X%.3f Y%.3f Z-15 R2 F200", cx - 15, cy);
    line(out, "X%.3f", cx + 15);
  }
  out += "G80\nG0 Z20\nM5\nM30\n";

  p.tools = "[{\"number\":1,\"name\":\"FACE_D50\",\"type\":\"face_mill\",\"diameter\":50,\"length\":60},\n"
            " {\"number\":2,\"name\":\"ENDMILL_D10\",\"type\":\"flat_end_mill\",\"diameter\":10,\"length\":60},\n"
            " {\"number\":3,\"name\":\"DRILL_D8\",\"type\":\"drill\",\"diameter\":8,\"length\":80,\"point_angle\":118}]\n";
  char buf[160];
  std::snprintf(buf, sizeof buf, "{\"units\":\"mm\",\"shape\":\"block\",\"min\":[0,0,-30],\"max\":[%.3f,%.3f,1]}\n", width, height);
  p.stock = buf;
  return p;
}

}  // namespace ncbridge::bench
