// The arc acceptance rule against LinuxCNC's rs274: arcs generated on both sides of every
// tolerance boundary (the I/J/K end-radius check: absolute, relative, 100x absolute; the R-format
// reach check; the zero-radius check), in mm and inch, in the three planes, clockwise and
// counter-clockwise, with the end radius larger and smaller than the start radius. Each arc is
// run through rs274 (its verdict is the truth) and through ncbridge in RS274/NGC, and the XY
// arcs also as Fanuc, Mach3, SINUMERIK 840D and Heidenhain programs: every dialect's default
// tolerance is LinuxCNC's, so every verdict must be rs274's.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "support/run_program.hpp"

namespace fs = std::filesystem;
using ncbridge::interpreter::Dialect;

namespace {

constexpr double kSqrt2 = 1.4142135623730951;
struct UnitTolerances {
  bool inch;
  double center;  // CENTER_ARC_RADIUS_TOLERANCE
  double radius;  // RADIUS_TOLERANCE (R format, zero radius)
};
constexpr UnitTolerances kMm{false, 2 * 0.01 * kSqrt2, 0.00127};
constexpr UnitTolerances kInch{true, 2 * 0.001 * kSqrt2, 0.00005};

enum class Plane { XY, XZ, YZ };

// One G2/G3 from `start` about `center` (absolute, in the plane's first and second axes) to
// `end`, or in R format with `radius`.
struct ArcCase {
  std::string what;
  bool inch = false;
  Plane plane = Plane::XY;
  bool clockwise = true;
  double start1 = 0, start2 = 0, center1 = 0, center2 = 0, end1 = 0, end2 = 0;
  bool r_format = false;
  double radius = 0;
};

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10f", v);
  return buf;
}

// Heidenhain writes a sign on every coordinate.
std::string signed_num(double v) { return (v < 0 ? "" : "+") + num(v); }

struct PlaneWords {
  const char* select;
  char first, second, first_offset, second_offset;
};

PlaneWords words_of(Plane p) {
  switch (p) {
    case Plane::XZ: return {"G18", 'Z', 'X', 'K', 'I'};
    case Plane::YZ: return {"G19", 'Y', 'Z', 'J', 'K'};
    default: return {"G17", 'X', 'Y', 'I', 'J'};
  }
}

std::string rs274ngc_program(const ArcCase& c) {
  const PlaneWords w = words_of(c.plane);
  std::ostringstream p;
  p << (c.inch ? "G20" : "G21") << " " << w.select << " G90 G94\n";
  p << "G0 " << w.first << num(c.start1) << " " << w.second << num(c.start2) << "\n";
  p << (c.clockwise ? "G2 " : "G3 ") << w.first << num(c.end1) << " " << w.second << num(c.end2) << " ";
  if (c.r_format) {
    p << "R" << num(c.radius);
  } else {
    p << w.first_offset << num(c.center1 - c.start1) << " " << w.second_offset << num(c.center2 - c.start2);
  }
  p << " F100\nM2\n";
  return p.str();
}

// The same XY arc as a program of the Fanuc and Mach3 controllers (decimal points on every value).
std::string fanuc_program(const ArcCase& c, bool mach3) {
  std::ostringstream p;
  if (!mach3) p << "%\nO1000\n";
  p << (c.inch ? "G20" : "G21") << " G17 G90 G94\n";
  p << "G0 X" << num(c.start1) << " Y" << num(c.start2) << "\n";
  p << (c.clockwise ? "G2 X" : "G3 X") << num(c.end1) << " Y" << num(c.end2);
  if (c.r_format) {
    p << " R" << num(c.radius);
  } else {
    p << " I" << num(c.center1 - c.start1) << " J" << num(c.center2 - c.start2);
  }
  p << " F100.\nM30\n";
  if (!mach3) p << "%\n";
  return p.str();
}

std::string siemens_program(const ArcCase& c) {
  std::ostringstream p;
  p << (c.inch ? "G70" : "G71") << " G17 G90 G94\n";
  p << "G0 X" << num(c.start1) << " Y" << num(c.start2) << "\n";
  p << (c.clockwise ? "G2 X" : "G3 X") << num(c.end1) << " Y" << num(c.end2);
  if (c.r_format) {
    p << " CR=" << num(c.radius);
  } else {
    p << " I" << num(c.center1 - c.start1) << " J" << num(c.center2 - c.start2);
  }
  p << " F100\nM30\n";
  return p.str();
}

// Heidenhain: the centre by CC (absolute), the arc by C to its end point.
std::string heidenhain_program(const ArcCase& c) {
  const char* unit = c.inch ? "INCH" : "MM";
  std::ostringstream p;
  p << "0 BEGIN PGM ARC " << unit << "\n";
  p << "1 L X" << signed_num(c.start1) << " Y" << signed_num(c.start2) << " R0 FMAX\n";
  p << "2 CC X" << signed_num(c.center1) << " Y" << signed_num(c.center2) << "\n";
  p << "3 C X" << signed_num(c.end1) << " Y" << signed_num(c.end2) << (c.clockwise ? " DR-" : " DR+") << " F100\n";
  p << "4 END PGM ARC " << unit << "\n";
  return p.str();
}

class NullSink final : public ncbridge::canonical::Sink {
 public:
  void call(const ncbridge::canonical::Call&) override {}
};

// ncbridge's verdict: true when the program runs; the refusal's message otherwise.
bool ncbridge_accepts(const std::string& text, Dialect dialect, const std::string& name, std::string* why) {
  ncbridge::interpreter::Options options;
  options.dialect = dialect;
  NullSink sink;
  try {
    ncbridge::interpreter::interpret_text(text, name, options, sink);
    return true;
  } catch (const ncbridge::InputError& e) {
    *why = e.what();
    return false;
  }
}

// The cases: for each boundary, arcs at 0.9, 0.99, 0.999, 1.001, 1.01 and 1.1 of it, the end
// radius longer and shorter than the start radius, turned to several angles.
std::vector<ArcCase> boundary_cases() {
  std::vector<ArcCase> cases;
  const double factors[] = {0.9, 0.99, 0.999, 1.001, 1.01, 1.1};
  int turn = 0;
  auto place = [&](ArcCase c, double r_start, double r_end) {
    // start at angle a, end at angle a + 100 deg, centre at (cx, cy); plane and direction cycle.
    const double a = 0.37 * turn, b = a + 1.75;
    const double cx = 3.25 - 0.5 * (turn % 3), cy = -1.5 + 0.25 * (turn % 5);
    c.center1 = cx;
    c.center2 = cy;
    c.start1 = cx + r_start * std::cos(a);
    c.start2 = cy + r_start * std::sin(a);
    c.end1 = cx + r_end * std::cos(b);
    c.end2 = cy + r_end * std::sin(b);
    c.plane = static_cast<Plane>(turn % 3);
    c.clockwise = (turn / 3) % 2 == 0;
    ++turn;
    cases.push_back(c);
  };
  for (const UnitTolerances& u : {kMm, kInch}) {
    const double scale = u.inch ? 0.1 : 1.0;  // radii in the unit's usual range
    for (double f : factors) {
      for (int sign : {+1, -1}) {
        ArcCase c;
        c.inch = u.inch;
        // 1. absolute tolerance, on small arcs (the relative error is far over 0.1 %)
        for (double r : {1.0 * scale, 5.0 * scale}) {
          c.what = "absolute tolerance x" + num(f) + " r=" + num(r);
          place(c, r, r + sign * u.center * f);
        }
        // 2. relative tolerance (0.1 % of the larger radius), between the absolute and 100x absolute
        for (double r : {100.0 * scale, 500.0 * scale}) {
          c.what = "relative tolerance x" + num(f) + " r=" + num(r);
          const double err = 0.001 * r / (1 - 0.001) * f;  // err / (r + err) = 0.001 f, about
          place(c, r, r + sign * err);
        }
        // 3. 100x the absolute tolerance, on arcs so large that 0.1 % is more than that
        for (double r : {20000.0 * scale, 50000.0 * scale}) {
          c.what = "100x absolute tolerance x" + num(f) + " r=" + num(r);
          place(c, r, r + sign * 100 * u.center * f);
        }
      }
      // 4. R format: the chord's half length longer than |R| by the radius tolerance
      for (double r : {2.0 * scale, 40.0 * scale}) {
        ArcCase c;
        c.inch = u.inch;
        c.r_format = true;
        c.what = "R too small x" + num(f) + " R=" + num(r);
        c.radius = turn % 2 ? r : -r;
        const double half = r + u.radius * f;
        const double a = 0.29 * turn;
        c.start1 = 1.0 - half * std::cos(a);
        c.start2 = 2.0 - half * std::sin(a);
        c.end1 = 1.0 + half * std::cos(a);
        c.end2 = 2.0 + half * std::sin(a);
        c.plane = static_cast<Plane>(turn % 3);
        c.clockwise = turn % 2 == 0;
        ++turn;
        cases.push_back(c);
      }
      // 5. zero radius: both radii below the radius tolerance
      ArcCase z;
      z.inch = u.inch;
      z.what = "zero radius x" + num(f);
      place(z, u.radius * f, u.radius * f);
    }
  }
  return cases;
}

struct Rs274 {
  fs::path executable;
  fs::path scratch;
};

bool rs274_accepts(const Rs274& rs274, const std::string& text, std::string* why) {
  const fs::path program = rs274.scratch / "arc.ngc";
  std::ofstream(program) << text;
  ncbridge::testing::RunOptions options;
  options.extra_environment = {"HOME=" + rs274.scratch.string()};
  const auto run = ncbridge::testing::run_program({rs274.executable.string(), "-g", program.string()}, options);
  std::istringstream err(run.err);
  for (std::string line; std::getline(err, line);) {
    if (!line.empty() && line != "executing") {
      *why = line;
      return false;
    }
  }
  *why = "exit " + std::to_string(run.exit_code);
  return run.exit_code == 0;
}

}  // namespace

TEST(ArcTolerance, EveryDialectRefusesExactlyTheArcsRs274Refuses) {
  Rs274 rs274;
  rs274.executable = ncbridge::testing::find_on_path("rs274");
  if (rs274.executable.empty()) {
    if (ncbridge::testing::in_ci()) FAIL() << "rs274 not installed under CI=true (scripts/install-deps.sh --tests installs linuxcnc-uspace)";
    GTEST_SKIP() << "SKIPPED: rs274 not installed (Debian package linuxcnc-uspace)";
  }
  rs274.scratch = fs::temp_directory_path() / ("ncbridge-arc-tolerance-" + std::to_string(::getpid()));
  fs::create_directories(rs274.scratch);

  const auto cases = boundary_cases();
  int accepted = 0, refused = 0, dialect_checks = 0;
  for (const ArcCase& c : cases) {
    const std::string ngc = rs274ngc_program(c);
    std::string reference_why, why;
    const bool reference = rs274_accepts(rs274, ngc, &reference_why);
    (reference ? accepted : refused) += 1;
    const std::string label = c.what + (c.inch ? " (inch)" : " (mm)");
    EXPECT_EQ(ncbridge_accepts(ngc, Dialect::Rs274Ngc, "arc.ngc", &why), reference)
        << label << "\nrs274: " << reference_why << "\nncbridge: " << why << "\n" << ngc;
    if (c.plane != Plane::XY) continue;
    struct Variant {
      Dialect dialect;
      std::string name, text;
    };
    std::vector<Variant> variants = {{Dialect::Fanuc, "arc.nc", fanuc_program(c, false)},
                                     {Dialect::Mach3, "arc.tap", fanuc_program(c, true)},
                                     {Dialect::Siemens840D, "arc.mpf", siemens_program(c)}};
    if (!c.r_format) variants.push_back({Dialect::Heidenhain, "arc.h", heidenhain_program(c)});
    for (const auto& v : variants) {
      ++dialect_checks;
      EXPECT_EQ(ncbridge_accepts(v.text, v.dialect, v.name, &why), reference)
          << label << " as " << v.name << "\nrs274: " << reference_why << "\nncbridge: " << why << "\n" << v.text;
    }
  }
  std::error_code ignored;
  fs::remove_all(rs274.scratch, ignored);
  std::printf("arc tolerance: %zu arcs (%d accepted, %d refused by rs274), %d dialect programs\n", cases.size(),
              accepted, refused, dialect_checks);
  // Both sides of the boundaries are really exercised.
  EXPECT_GT(accepted, static_cast<int>(cases.size()) / 4);
  EXPECT_GT(refused, static_cast<int>(cases.size()) / 4);
}
