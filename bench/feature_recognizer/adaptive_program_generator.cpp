#include "adaptive_program_generator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace ncbridge::bench {
namespace {

class Random {  // SplitMix64, as the other generators
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  double uniform(double low, double high) {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return low + (high - low) * static_cast<double>(z >> 11) * 0x1p-53;
  }

 private:
  std::uint64_t state_;
};

constexpr double kCellX = 110, kCellY = 80;  // mm, one pocket per cell
constexpr double kRough = 10, kFinish = 6, kCorner = 4, kDepth = 8, kStepDown = 2, kAllowance = 0.3;
constexpr double kLoop = 2;  // trochoid loop radius

void line(std::string& out, const char* format, double a = 0, double b = 0, double c = 0, double d = 0, double e = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, format, a, b, c, d, e);
  out += buf;
  out += '\n';
}

struct Pocket {
  double cx, cy, length, width, advance, stepover;
};

// One level of trochoidal slots along X, from y low to high, each slot entered by a plunge
// after a lift (the first by a helix).
void rough_level(std::string& out, const Pocket& p, double z) {
  const double r = kRough / 2 + kAllowance + kLoop;  // from the wall to the slot's centre line
  const double x0 = p.cx - p.length / 2 + r, x1 = p.cx + p.length / 2 - r;
  const double y0 = p.cy - p.width / 2 + r, y1 = p.cy + p.width / 2 - r;
  const int slots = std::max(1, static_cast<int>(std::ceil((y1 - y0) / p.stepover)));
  for (int s = 0; s <= slots; ++s) {
    const double y = y0 + (y1 - y0) * s / slots;
    const bool forward = s % 2 == 0;
    const double xs = forward ? x0 : x1, dir = forward ? 1 : -1;
    line(out, "G0 X%.4f Y%.4f", xs, y - kLoop);
    if (s == 0) {  // helix entry: two turns down to the level
      line(out, "G1 Z%.4f F400", z + 1.5);
      line(out, "G3 X%.4f Y%.4f Z%.4f I0 J%.4f P2", xs, y - kLoop, z, kLoop);
    } else {
      line(out, "G1 Z%.4f F400", z);
    }
    const int loops = static_cast<int>((x1 - x0) / p.advance);
    double x = xs;
    for (int k = 0; k < loops; ++k) {
      // Up over the loop's far side, then down to the next loop's start, one advance on.
      const double nx = x + dir * p.advance;
      line(out, "G3 X%.4f Y%.4f I0 J%.4f F1800", x, y + kLoop, kLoop);
      line(out, "G3 X%.4f Y%.4f I%.4f J%.4f", nx, y - kLoop, dir * p.advance / 2, -kLoop);
      x = nx;
    }
    line(out, "G0 Z%.4f", z + 1);  // the adaptive link: lift, move over, plunge
  }
}

// The finishing contour at full depth, counter-clockwise, corners radius kCorner - tool radius.
void finish(std::string& out, const Pocket& p) {
  const double rc = kCorner - kFinish / 2;
  const double hx = p.length / 2 - kFinish / 2, hy = p.width / 2 - kFinish / 2;
  const double z = -kDepth;
  line(out, "G0 X%.4f Y%.4f", p.cx, p.cy);
  line(out, "G1 Z%.4f F300", z);
  line(out, "G1 X%.4f Y%.4f F900", p.cx + hx - rc, p.cy - hy);
  line(out, "G3 X%.4f Y%.4f I0 J%.4f", p.cx + hx, p.cy - hy + rc, rc);
  line(out, "G1 Y%.4f", p.cy + hy - rc);
  line(out, "G3 X%.4f Y%.4f I%.4f J0", p.cx + hx - rc, p.cy + hy, -rc);
  line(out, "G1 X%.4f", p.cx - hx + rc);
  line(out, "G3 X%.4f Y%.4f I0 J%.4f", p.cx - hx, p.cy + hy - rc, -rc);
  line(out, "G1 Y%.4f", p.cy - hy + rc);
  line(out, "G3 X%.4f Y%.4f I%.4f J0", p.cx - hx + rc, p.cy - hy, rc);
  line(out, "G1 X%.4f", p.cx + hx - rc);
  line(out, "G0 Z5");
}

}  // namespace

MillingProgram generate_adaptive_program(long lines, std::uint64_t seed) {
  // About 2 * (length / advance) * (width / stepover + 1) lines per level: ~5,000 per pocket.
  Random random(seed);
  std::vector<Pocket> pockets;
  long estimate = 0;
  while (estimate < lines - 20 || pockets.empty()) {
    Pocket p{};
    p.length = random.uniform(70, 90), p.width = random.uniform(40, 55);
    p.advance = random.uniform(0.6, 1.0), p.stepover = random.uniform(5, 7);
    const double slots = std::ceil((p.width - kRough - 2 * kAllowance - 2 * kLoop) / p.stepover) + 1;
    const long per_level = static_cast<long>(slots * (2 * (p.length - kRough - 2 * kAllowance - 2 * kLoop) / p.advance + 3));
    const long per_pocket = static_cast<long>(kDepth / kStepDown) * per_level + 13;
    if (!pockets.empty() && estimate + per_pocket > lines + per_pocket / 2) break;
    estimate += per_pocket;
    pockets.push_back(p);
  }
  const int columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(pockets.size())))));
  const int rows = (static_cast<int>(pockets.size()) + columns - 1) / columns;
  for (std::size_t i = 0; i < pockets.size(); ++i) {
    pockets[i].cx = (static_cast<double>(i % static_cast<std::size_t>(columns)) + 0.5) * kCellX;
    pockets[i].cy = (static_cast<double>(i / static_cast<std::size_t>(columns)) + 0.5) * kCellY;
  }
  MillingProgram out;
  out.cells = static_cast<int>(pockets.size());
  auto& text = out.program;
  text.reserve(static_cast<std::size_t>(lines) * 36);
  text += "G21 G90 G17 G40 G49 G54 G94\nT1 M6\nG43 H1\nS9000 M3\nG0 Z5\n";
  for (const auto& p : pockets) {
    for (double z = -kStepDown; z >= -kDepth - 1e-9; z -= kStepDown) rough_level(text, p, z);
    line(text, "G0 Z5");
  }
  text += "T2 M6\nG43 H2\nS12000 M3\nG0 Z5\n";
  for (const auto& p : pockets) finish(text, p);
  text += "M5\nM30\n";
  out.tools = "[{\"number\":1,\"name\":\"ENDMILL_D10\",\"type\":\"flat_end_mill\",\"diameter\":10,\"length\":60},\n"
              " {\"number\":2,\"name\":\"ENDMILL_D6\",\"type\":\"flat_end_mill\",\"diameter\":6,\"length\":50}]\n";
  char buf[160];
  std::snprintf(buf, sizeof buf, "{\"units\":\"mm\",\"shape\":\"block\",\"min\":[0,0,-20],\"max\":[%.3f,%.3f,0]}\n",
                columns * kCellX, rows * kCellY);
  out.stock = buf;
  return out;
}

}  // namespace ncbridge::bench
