#include "random_moves_generator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace ncbridge::bench {
namespace {

// SplitMix64: the same sequence on every platform (std distributions are not).
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double low, double high) { return low + (high - low) * static_cast<double>(next() >> 11) * 0x1p-53; }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }

 private:
  std::uint64_t state_;
};

constexpr double kWidth = 300, kHeight = 200, kTop = 0, kBottom = -40, kSafe = 5;

struct Tool {
  int number;
  double diameter;
  bool drill;
};
constexpr Tool kTools[] = {{1, 40, false}, {2, 12, false}, {3, 6, false}, {4, 3, false}, {5, 10, true}, {6, 8, true}};

class Writer {
 public:
  Writer(long lines, std::uint64_t seed, std::string& out) : target_(lines), random_(seed), out_(out) {}

  void write() {
    emit("G21 G90 G17 G40 G49 G54 G94");
    while (written_ < target_ - 4) {
      change_tool();
      const long until = std::min(target_ - 4, written_ + 200 + random_.below(4000));
      while (written_ < until) tool_.drill ? drill() : walk(until);
      emit("G0 Z%.3f", kSafe);
    }
    emit("G80");
    emit("G0 Z%.3f", 2 * kSafe);
    emit("M5");
    emit("M30");
  }

 private:
  template <typename... Args>
  void emit(const char* format, Args... args) {
    char line[160];
    const int length = std::snprintf(line, sizeof line, format, args...);
    out_.append(line, static_cast<std::size_t>(length));
    out_.push_back('\n');
    ++written_;
  }

  double clamp_x(double x) const { return std::clamp(x, -5.0, kWidth + 5); }
  double clamp_y(double y) const { return std::clamp(y, -5.0, kHeight + 5); }

  void change_tool() {
    tool_ = kTools[random_.below(6)];
    emit("T%d M6", tool_.number);
    emit("G43 H%d", tool_.number);
    emit("S%d M3", 2000 + 1000 * random_.below(8));
  }

  void drill() {
    const double x = random_.uniform(0, kWidth), y = random_.uniform(0, kHeight);
    const double depth = random_.uniform(1, 30);
    if (random_.below(2) == 0) {
      emit("G81 X%.3f Y%.3f Z%.3f R2 F%d", x, y, -depth, 100 + 20 * random_.below(10));
    } else {
      emit("G83 X%.3f Y%.3f Z%.3f R2 Q%.3f F%d", x, y, -depth, random_.uniform(1, 5), 100 + 20 * random_.below(10));
    }
    cycle_ = true;
    if (random_.below(8) == 0) {
      emit("G80");
      cycle_ = false;
    }
  }

  // A random walk at one depth (with some ramps and helices on the way), entered from above.
  void walk(long until) {
    x_ = random_.uniform(0, kWidth), y_ = random_.uniform(0, kHeight);
    z_ = -random_.uniform(0.2, tool_.diameter >= 40 ? 3 : 15);
    if (cycle_) emit("G80");
    cycle_ = false;
    emit("G0 X%.3f Y%.3f Z%.3f", x_, y_, kSafe);
    if (random_.below(3) == 0) {  // ramp in
      const double a = random_.uniform(0, 2 * std::numbers::pi), l = random_.uniform(5, 30);
      x_ = clamp_x(x_ + l * std::cos(a)), y_ = clamp_y(y_ + l * std::sin(a));
      emit("G1 X%.3f Y%.3f Z%.3f F%d", x_, y_, z_, 300 + 50 * random_.below(10));
    } else {
      emit("G1 Z%.3f F%d", z_, 200 + 50 * random_.below(6));
    }
    const long moves = 5 + random_.below(random_.below(4) == 0 ? 400 : 60);
    for (long m = 0; m < moves && written_ < until; ++m) {
      const int kind = random_.below(20);
      if (kind < 12) {
        // Mostly short moves, some long: lengths spread over two orders of magnitude.
        const double a = random_.uniform(0, 2 * std::numbers::pi), l = std::exp(random_.uniform(std::log(0.2), std::log(60.0)));
        x_ = clamp_x(x_ + l * std::cos(a)), y_ = clamp_y(y_ + l * std::sin(a));
        if (random_.below(5) == 0) {
          emit("G1 X%.3f Y%.3f F%d", x_, y_, 400 + 100 * random_.below(20));
        } else {
          emit("G1 X%.3f Y%.3f", x_, y_);
        }
      } else if (kind < 18) {
        arc(false);
      } else if (kind < 19) {
        arc(true);
      } else {
        z_ = std::max(kBottom + 1, std::min(kTop - 0.1, z_ + random_.uniform(-2, 1)));
        const double a = random_.uniform(0, 2 * std::numbers::pi), l = random_.uniform(2, 20);
        x_ = clamp_x(x_ + l * std::cos(a)), y_ = clamp_y(y_ + l * std::sin(a));
        emit("G1 X%.3f Y%.3f Z%.3f", x_, y_, z_);
      }
    }
  }

  // An arc from the current point about a random centre (I J form), helical when asked.
  void arc(bool helical) {
    const double r = random_.uniform(1, 25), start = random_.uniform(0, 2 * std::numbers::pi);
    const double cx = x_ - r * std::cos(start), cy = y_ - r * std::sin(start);
    const double sweep = random_.uniform(0.3, 2 * std::numbers::pi - 0.3);
    const bool clockwise = random_.below(2) == 0;
    const double end = start + (clockwise ? -sweep : sweep);
    const double ex = cx + r * std::cos(end), ey = cy + r * std::sin(end);
    if (helical) {
      z_ = std::max(kBottom + 1, z_ - random_.uniform(0.2, 2));
      emit("G%d X%.4f Y%.4f Z%.3f I%.4f J%.4f", clockwise ? 2 : 3, ex, ey, z_, cx - x_, cy - y_);
    } else {
      emit("G%d X%.4f Y%.4f I%.4f J%.4f", clockwise ? 2 : 3, ex, ey, cx - x_, cy - y_);
    }
    x_ = std::round(ex * 1e4) / 1e4;
    y_ = std::round(ey * 1e4) / 1e4;
  }

  long target_;
  long written_ = 0;
  Random random_;
  std::string& out_;
  Tool tool_{};
  double x_ = 0, y_ = 0, z_ = 0;
  bool cycle_ = false;  // a canned cycle is active (G80 cancels it before other motion)
};

}  // namespace

MillingProgram generate_random_moves_program(long lines, std::uint64_t seed) {
  MillingProgram p;
  p.program.reserve(static_cast<std::size_t>(lines) * 30);
  Writer(lines, seed, p.program).write();
  p.tools = "[{\"number\":1,\"name\":\"FACE_D40\",\"type\":\"face_mill\",\"diameter\":40,\"length\":60},\n"
            " {\"number\":2,\"name\":\"ENDMILL_D12\",\"type\":\"flat_end_mill\",\"diameter\":12,\"length\":70},\n"
            " {\"number\":3,\"name\":\"ENDMILL_D6\",\"type\":\"flat_end_mill\",\"diameter\":6,\"length\":50},\n"
            " {\"number\":4,\"name\":\"ENDMILL_D3\",\"type\":\"flat_end_mill\",\"diameter\":3,\"length\":40},\n"
            " {\"number\":5,\"name\":\"SPOT_D10\",\"type\":\"spot_drill\",\"diameter\":10,\"length\":60,\"point_angle\":90},\n"
            " {\"number\":6,\"name\":\"DRILL_D8\",\"type\":\"drill\",\"diameter\":8,\"length\":90,\"point_angle\":118}]\n";
  char buf[160];
  std::snprintf(buf, sizeof buf, "{\"units\":\"mm\",\"shape\":\"block\",\"min\":[0,0,%.3f],\"max\":[%.3f,%.3f,%.3f]}\n",
                kBottom, kWidth, kHeight, kTop);
  p.stock = buf;
  return p;
}

}  // namespace ncbridge::bench
