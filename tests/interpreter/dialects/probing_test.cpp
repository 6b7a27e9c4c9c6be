// Probing in the controller dialects, through the library API: Fanuc G31 skip, Mach3 G31 probe,
// SINUMERIK MEAS=/MEAW= measuring, Heidenhain TCH PROBE 0 (reference plane). Each is a probe
// move (STRAIGHT_PROBE, LinuxCNC's G38.3 or G38.5); what a construct cannot be read as is a
// located "not supported: ..." error (so are SINUMERIK's spline interpolations). The moves around
// them are checked against rs274 by the single-construct programs in <dialect>/.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/interpreter.hpp"

namespace {

using ncbridge::InputError;
using ncbridge::canonical::Call;
using ncbridge::interpreter::Dialect;

struct Collect final : ncbridge::canonical::Sink {
  void call(const Call& c) override { calls.push_back(c); }
  std::vector<Call> calls;
  std::vector<ncbridge::canonical::StraightProbe> probes() const {
    std::vector<ncbridge::canonical::StraightProbe> out;
    for (const auto& c : calls) {
      if (const auto* p = std::get_if<ncbridge::canonical::StraightProbe>(&c.data)) out.push_back(*p);
    }
    return out;
  }
  std::vector<ncbridge::canonical::Pose> traverses() const {
    std::vector<ncbridge::canonical::Pose> out;
    for (const auto& c : calls) {
      if (const auto* t = std::get_if<ncbridge::canonical::StraightTraverse>(&c.data)) out.push_back(t->end);
    }
    return out;
  }
};

Collect run(const std::string& text, Dialect dialect) {
  ncbridge::interpreter::Options options;
  options.dialect = dialect;
  Collect sink;
  ncbridge::interpreter::interpret_text(text, "probe.prog", options, sink);
  return sink;
}

InputError error_of(const std::string& text, Dialect dialect) {
  try {
    run(text, dialect);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError({}, "");
}

TEST(FanucSkip, G31IsAProbeMoveThatStopsWithoutAlarmAndIsOneShot) {
  const auto out = run("G21 G90 G17\nG0 X10. Y10. Z20.\nG31 Z-5. F100.\nX20.\nM30\n", Dialect::Fanuc);
  const auto probes = out.probes();
  ASSERT_EQ(probes.size(), 1u);
  EXPECT_EQ(probes[0].probe_type, 1);  // G38.3: no error without contact
  EXPECT_DOUBLE_EQ(probes[0].end.z, -5);
  const auto rapids = out.traverses();
  ASSERT_EQ(rapids.size(), 2u);  // X20. moves in G0 again
  EXPECT_DOUBLE_EQ(rapids[1].x, 20);
}

TEST(FanucSkip, MultiStepSkipIsReportedWhereItIs) {
  const InputError e = error_of("G21 G90\nG0 X0 Y0 Z10.\nG31 P2 Z-5. F100.\nM30\n", Dialect::Fanuc);
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().column, 5u);
  EXPECT_NE(std::string(e.what()).find("not supported"), std::string::npos) << e.what();
}

TEST(Mach3Probe, TripPointComesBackInParameters2000To2002) {
  const auto out = run("G21 G90\nG0 X1 Y2 Z20\nG31 Z-7 F100\nG0 X[#2000 + 10] Y#2001 Z[#2002 + 3]\nM30\n", Dialect::Mach3);
  ASSERT_EQ(out.probes().size(), 1u);
  const auto rapids = out.traverses();
  ASSERT_EQ(rapids.size(), 2u);
  EXPECT_DOUBLE_EQ(rapids[1].x, 11);
  EXPECT_DOUBLE_EQ(rapids[1].y, 2);
  EXPECT_DOUBLE_EQ(rapids[1].z, -4);
}

TEST(SinumerikMeasuring, MeasAndMeawAreProbeMovesReadBackThroughAaMw) {
  const auto out = run("G17 G71 G90\nG0 X5 Y5 Z20\nMEAS=1 G1 Z-10 F100\nR1=$AA_MW[Z] R2=$AC_MEA[1] R3=$AC_MEA[2]\n"
                       "G0 Z=R1+R2*10+R3*100\nMEAW=-2 X30\nG0 X=$AA_MW[X]+$AC_MEA[2]\nM30\n",
                       Dialect::Siemens840D);
  const auto probes = out.probes();
  ASSERT_EQ(probes.size(), 2u);
  EXPECT_EQ(probes[0].probe_type, 1);  // rising edge: G38.3
  EXPECT_EQ(probes[1].probe_type, 3);  // falling edge: G38.5
  const auto rapids = out.traverses();
  ASSERT_EQ(rapids.size(), 3u);
  EXPECT_DOUBLE_EQ(rapids[1].z, 0);   // -10 + 1 * 10 + 0 * 100: probe 2 not triggered yet
  EXPECT_DOUBLE_EQ(rapids[2].x, 31);  // 30 + 1
}

TEST(SinumerikMeasuring, ErrorsAreLocated) {
  const InputError circle = error_of("G17 G71 G90\nG0 X0 Y0 Z5\nMEAS=1 G2 X10 Y0 CR=5 F100\nM30\n", Dialect::Siemens840D);
  EXPECT_EQ(circle.where().line, 3u);
  EXPECT_EQ(circle.where().column, 1u);
  EXPECT_NE(std::string(circle.what()).find("not supported: measuring"), std::string::npos) << circle.what();
  const InputError probe = error_of("G17 G71 G90\nG0 X0 Y0 Z5\nG1 F100 MEAW=3 Z0\nM30\n", Dialect::Siemens840D);
  EXPECT_EQ(probe.where().column, 9u);
  const InputError axis = error_of("G17 G71 G90\nR1=$AA_MW[Q]\nM30\n", Dialect::Siemens840D);
  EXPECT_EQ(axis.where().line, 2u);
  EXPECT_NE(std::string(axis.what()).find("X, Y, Z"), std::string::npos) << axis.what();
}

TEST(HeidenhainTouchProbe, ReferencePlaneProbesFromThePrePositionAndSavesTheResult) {
  const auto out = run("0 BEGIN PGM P MM\n1 L Z+50 R0 FMAX\n2 TCH PROBE 0.0 REF. PLANE Q7 Y+\n"
                       "3 TCH PROBE 0.1 X+5 Y-30 Z-2\n4 L Y+Q7 FMAX\n5 END PGM P MM\n",
                       Dialect::Heidenhain);
  const auto probes = out.probes();
  ASSERT_EQ(probes.size(), 1u);
  EXPECT_EQ(probes[0].probe_type, 1);
  EXPECT_DOUBLE_EQ(probes[0].end.y, -10);  // 20 mm (the table's measuring range) in +Y
  const auto rapids = out.traverses();
  ASSERT_EQ(rapids.size(), 4u);  // Z+50, to the pre-position, back to it, Y+Q7
  EXPECT_DOUBLE_EQ(rapids[2].y, -30);
  EXPECT_DOUBLE_EQ(rapids[3].y, -10);
}

TEST(HeidenhainTouchProbe, OtherProbingCyclesAreReportedWhereTheyAre) {
  const InputError e = error_of("0 BEGIN PGM P MM\n1 TCH PROBE 410 NULLPUNKT RECHTECK INNEN\n2 END PGM P MM\n",
                                Dialect::Heidenhain);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 13u);
  EXPECT_NE(std::string(e.what()).find("not supported: probing cycle 410"), std::string::npos) << e.what();
  const InputError polar = error_of("0 BEGIN PGM P MM\n1 TCH PROBE 1.0 POLAR DATUM PLANE\n2 END PGM P MM\n",
                                    Dialect::Heidenhain);
  EXPECT_NE(std::string(polar.what()).find("probing cycle 1 "), std::string::npos) << polar.what();
  const InputError alone = error_of("0 BEGIN PGM P MM\n1 TCH PROBE 0.1 X+0 Y+0 Z+0\n2 END PGM P MM\n",
                                    Dialect::Heidenhain);
  EXPECT_NE(std::string(alone.what()).find("without its TCH PROBE 0.0"), std::string::npos) << alone.what();
}

TEST(SinumerikSplines, SplineInterpolationIsReportedNotCalledAsASubprogram) {
  const InputError e = error_of("G17 G71 G90\nG0 X0 Y0\nBSPLINE G1 X10 Y10 F100\nM30\n", Dialect::Siemens840D);
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().column, 1u);
  EXPECT_NE(std::string(e.what()).find("not supported: spline interpolation BSPLINE"), std::string::npos) << e.what();
}

}  // namespace
