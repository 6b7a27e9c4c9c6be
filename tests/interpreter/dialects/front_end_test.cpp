// Dialect front-ends through the library API: detection, error locations (file, line, column)
// and single constructs whose canonical result is known by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <fstream>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace {

using ncbridge::InputError;
using ncbridge::canonical::Call;
using ncbridge::interpreter::Dialect;

class Collect final : public ncbridge::canonical::Sink {
 public:
  void call(const Call& c) override { calls.push_back(c); }
  std::vector<Call> calls;
  // end points of the feed and traverse moves, and arcs' end points
  std::vector<std::array<double, 3>> ends() const {
    std::vector<std::array<double, 3>> out;
    for (const auto& c : calls) {
      if (auto* f = std::get_if<ncbridge::canonical::StraightFeed>(&c.data)) out.push_back({f->end.x, f->end.y, f->end.z});
      if (auto* t = std::get_if<ncbridge::canonical::StraightTraverse>(&c.data)) out.push_back({t->end.x, t->end.y, t->end.z});
      if (auto* a = std::get_if<ncbridge::canonical::ArcFeed>(&c.data)) out.push_back({a->first_end, a->second_end, a->axis_end_point});
    }
    return out;
  }
};

Collect run(const std::string& text, const ncbridge::interpreter::Options& options, const std::string& name = "test.prog") {
  Collect sink;
  ncbridge::interpreter::interpret_text(text, name, options, sink);
  return sink;
}

Collect run(const std::string& text, Dialect dialect, const std::string& name = "test.prog") {
  ncbridge::interpreter::Options options;
  options.dialect = dialect;
  return run(text, options, name);
}

// Options for `dialect` with T1 a 10 mm flat end mill (pocket cycles need its diameter).
ncbridge::interpreter::Options with_mill(Dialect dialect) {
  ncbridge::interpreter::Options options;
  options.dialect = dialect;
  ncbridge::setup::Tool mill;
  mill.number = 1;
  mill.type = ncbridge::setup::ToolType::FlatEndMill;
  mill.diameter = 10.0;
  mill.length = 50.0;
  options.tools = ncbridge::setup::ToolList({mill});
  return options;
}

InputError error_of(const std::string& text, const ncbridge::interpreter::Options& options) {
  try {
    run(text, options);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError({}, "");
}

InputError error_of(const std::string& text, Dialect dialect) {
  ncbridge::interpreter::Options options;
  options.dialect = dialect;
  return error_of(text, options);
}

bool near(const std::array<double, 3>& p, double x, double y, double z) {
  return std::fabs(p[0] - x) < 1e-6 && std::fabs(p[1] - y) < 1e-6 && std::fabs(p[2] - z) < 1e-6;
}

// ---- detection

TEST(DialectDetection, NamesTheDialectAndItsEvidence) {
  using ncbridge::interpreter::detect_dialect;
  EXPECT_EQ(detect_dialect("0 BEGIN PGM X MM\n1 L X+10 FMAX\n").dialect, Dialect::Heidenhain);
  EXPECT_EQ(detect_dialect("N10 G0 X0\nN20 T=\"MILL\" M6\n").dialect, Dialect::Siemens840D);
  EXPECT_EQ(detect_dialect("N10 R1=5\nN20 G1 X=R1\n").dialect, Dialect::Siemens840D);
  EXPECT_EQ(detect_dialect("%\nO1234\nG0 X1.\nM30\n%\n").dialect, Dialect::Fanuc);
  EXPECT_EQ(detect_dialect("#1=5\nWHILE [#1 GT 0] DO 1\n").dialect, Dialect::Fanuc);
  EXPECT_EQ(detect_dialect("(Post Processor: PathScripts.post.mach3_mach4_post)\nG0 X0\n").dialect, Dialect::Mach3);
  EXPECT_EQ(detect_dialect("o100 sub\no100 endsub\nM2\n").dialect, Dialect::Rs274Ngc);
  auto plain = detect_dialect("G0 X1 Y2\nM2\n");
  EXPECT_EQ(plain.dialect, Dialect::Rs274Ngc);
  EXPECT_NE(plain.reason.find("assumed"), std::string::npos);
  auto fanuc = detect_dialect("%\n\nO0001 (PART)\n");
  EXPECT_NE(fanuc.reason.find("line 3"), std::string::npos) << fanuc.reason;
}

TEST(DialectDetection, NamesRoundTrip) {
  for (Dialect d : {Dialect::Rs274Ngc, Dialect::Fanuc, Dialect::Mach3, Dialect::Siemens840D, Dialect::Heidenhain,
                    Dialect::Auto}) {
    Dialect back = Dialect::Rs274Ngc;
    ASSERT_TRUE(ncbridge::interpreter::parse_dialect_name(ncbridge::interpreter::dialect_name(d), back));
    EXPECT_EQ(back, d);
  }
  Dialect unused;
  EXPECT_FALSE(ncbridge::interpreter::parse_dialect_name("sinumerik", unused));
}

// ---- Fanuc

TEST(Fanuc, DimensionWordsWithoutDecimalPointAreLeastIncrements) {
  auto sink = run("G21 G90 G0 X100 Y25. Z1000\nM30\n", Dialect::Fanuc);
  ASSERT_EQ(sink.ends().size(), 1u);
  EXPECT_TRUE(near(sink.ends()[0], 0.1, 25.0, 1.0));
}

TEST(Fanuc, PolarCoordinatesAboutTheLocalOrigin) {
  auto sink = run("G21 G90 G52 X10. Y10.\nG16\nG0 X5. Y90.\nY180.\nG15\nM30\n", Dialect::Fanuc);
  auto e = sink.ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_TRUE(near(e[0], 10.0, 15.0, 0.0));
  EXPECT_TRUE(near(e[1], 5.0, 10.0, 0.0));
}

TEST(Fanuc, RotationG68TurnsProgrammedPositions) {
  auto sink = run("G21 G90 G68 X0 Y0 R90.\nG0 X10. Y0\nG69\nG0 X10. Y0\nM30\n", Dialect::Fanuc);
  auto e = sink.ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_TRUE(near(e[0], 0.0, 10.0, 0.0));
  EXPECT_TRUE(near(e[1], 10.0, 0.0, 0.0));
}

TEST(Fanuc, RotationInsideALocalCoordinateSystemAndBack) {
  // G52 shifts by (10, 0); G68 turns 90 degrees about the local origin; G69 keeps the shift
  auto sink = run("G21 G90 G52 X10. Y0\nG68 X0 Y0 R90.\nG0 X5. Y0\nG69\nG0 X5. Y0\nG52 X0 Y0\nG0 X5. Y0\nM30\n",
                  Dialect::Fanuc);
  auto e = sink.ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_TRUE(near(e[0], 10.0, 5.0, 0.0));
  EXPECT_TRUE(near(e[1], 15.0, 0.0, 0.0));
  EXPECT_TRUE(near(e[2], 5.0, 0.0, 0.0));
}

TEST(Fanuc, SubprogramWithPackedRepeatCountAndMacroLoop) {
  const std::string program =
      "O0001\nG21 G90 G0 X0 Y0 Z0\nM98 P31000\nM30\n"
      "O1000\n#100=#100+1.\nG91 G0 X1.\nG90\nM99\n";
  auto sink = run(program, Dialect::Fanuc);
  auto e = sink.ends();
  ASSERT_EQ(e.size(), 4u);
  EXPECT_TRUE(near(e[3], 3.0, 0.0, 0.0));
  auto loop = run("G21 G90\n#1=0\nWHILE [#1 LT 3] DO 1\nG0 X#1\n#1=#1+1\nEND 1\nM30\n", Dialect::Fanuc);
  ASSERT_EQ(loop.ends().size(), 3u);
  EXPECT_TRUE(near(loop.ends()[2], 2.0, 0.0, 0.0));
}

TEST(Fanuc, EndlessLoopStopsWithAnError) {
  auto e = error_of("G21\nN10 G0 X1.\nGOTO 10\n", Dialect::Fanuc);
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_NE(e.message().find("endless loop"), std::string::npos);
  auto s = error_of("G71\nLOOP: R1=R1+1\nGOTOB LOOP\n", Dialect::Siemens840D);
  EXPECT_NE(s.message().find("endless loop"), std::string::npos);
  auto h = error_of("0 BEGIN PGM T MM\n1 LBL 1\n2 FN 9: IF +0 EQU +0 GOTO LBL 1\n3 END PGM T MM\n", Dialect::Heidenhain);
  EXPECT_NE(h.message().find("endless loop"), std::string::npos);
}

TEST(Fanuc, MacroAlarmStopsWithItsMessage) {
  auto e = error_of("G21\n#3000=12 (TOOL MISSING)\nM30\n", Dialect::Fanuc);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_NE(e.message().find("TOOL MISSING"), std::string::npos);
}

TEST(Fanuc, ErrorsAreLocated) {
  auto e = error_of("G21 G90\nG0 X1. Y[#1+]\nM30\n", Dialect::Fanuc);
  EXPECT_EQ(e.where().file, "test.prog");
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 13u);
  e = error_of("G21\nG1 X5. F100\nG12.1 X1.\nM30\n", Dialect::Fanuc);
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().column, 1u);
  e = error_of("G21\nGOTO 99\nM30\n", Dialect::Fanuc);
  EXPECT_EQ(e.where().line, 2u);
  e = error_of("G21\nM98 P5000\nM30\n", Dialect::Fanuc);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 1u);
  EXPECT_NE(e.message().find("O5000"), std::string::npos);
}

TEST(Fanuc, TappingAndBoringCyclesTagTheirHoles) {
  const std::string program =
      "G21 G90 G17\nS400 M4\nG0 Z30.\nG99 G74 X10. Y10. Z-12. R3. F280\nG80 M3\nG0 Z30.\n"
      "G98 G76 X20. Y10. Z-15. R2. Q0.5 F60\nG80\nG87 X40. Y10. Z-5. R-22. Q1. F50\nG80\nM30\n";
  auto sink = run(program, Dialect::Fanuc);
  std::map<std::uint32_t, ncbridge::canonical::CycleTag> holes;
  int orients = 0;
  for (const auto& c : sink.calls) {
    if (c.cycle) holes[c.cycle->cycle_id] = *c.cycle;
    if (std::holds_alternative<ncbridge::canonical::OrientSpindle>(c.data)) {
      ++orients;
      EXPECT_TRUE(c.cycle.has_value()) << "an oriented stop outside a hole";
    }
  }
  ASSERT_EQ(holes.size(), 3u);
  auto it = holes.begin();
  EXPECT_EQ(it->second.g_code_x10, 740);
  EXPECT_TRUE(it->second.retract_to_r);
  ++it;
  EXPECT_EQ(it->second.g_code_x10, 860);  // fine boring: boring, spindle stopped at the bottom
  EXPECT_FALSE(it->second.retract_to_r);
  EXPECT_DOUBLE_EQ(it->second.q, 0.5);
  EXPECT_DOUBLE_EQ(it->second.z, -15.0);
  EXPECT_DOUBLE_EQ(it->second.clearance, 30.0);
  ++it;
  EXPECT_EQ(it->second.g_code_x10, 870);
  EXPECT_DOUBLE_EQ(it->second.r, -22.0);
  EXPECT_DOUBLE_EQ(it->second.z, -5.0);
  EXPECT_DOUBLE_EQ(it->second.x, 40.0);
  EXPECT_EQ(orients, 3);  // one at the G76 bottom, two in G87 (above the part and at Z)
  // the shift at the G76 bottom: +X by Q, at the hole bottom
  auto e = sink.ends();
  bool shifted = false;
  for (const auto& p : e) shifted = shifted || near(p, 20.5, 10.0, -15.0);
  EXPECT_TRUE(shifted);
}

TEST(Fanuc, CycleRepeatsBeyondTheIterationLimitAreAnError) {
  auto e = error_of("G21 G90\nS400 M3\nG0 Z30.\nG91 G81 X1. Z-2. R-1. F80 K1000000000\nM30\n", Dialect::Fanuc);
  EXPECT_EQ(e.where().line, 4u);
  EXPECT_EQ(e.where().column, 27u);  // the K word
  EXPECT_NE(e.message().find("iteration limit"), std::string::npos) << e.message();
}

TEST(Fanuc, TappingAndBoringErrorsAreLocated) {
  auto e = error_of("G21 G90\nS400 M3\nG0 Z30.\nG99 G74 X10. Y10. Z-12. R3. F280\nM30\n", Dialect::Fanuc);
  EXPECT_EQ(e.where().line, 4u);
  EXPECT_EQ(e.where().column, 5u);
  EXPECT_NE(e.message().find("clockwise in G74"), std::string::npos) << e.message();
  e = error_of("G21 G90\nS400 M3\nG0 Z30.\nG87 X10. Y10. Z-12. R3. Q1. F80\nM30\n", Dialect::Fanuc);
  EXPECT_EQ(e.where().line, 4u);
  EXPECT_NE(e.message().find("G87"), std::string::npos) << e.message();
  e = error_of("G21 G90\nG0 Z30.\nG76 X10. Y10. Z-12. R3. Q1. F80\nM30\n", Dialect::Fanuc);
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_NE(e.message().find("Spindle not turning in G76"), std::string::npos) << e.message();
}

// Programs are read as streams (a line at a time, jumps seek back by file offset): loops and
// jumps across many lines, CRLF line ends and a last line without one, from a file and from text.
TEST(DialectStreams, JumpsAcrossLongProgramsFromFileAndText) {
  std::string fanuc = "G21 G90\r\n#1=0\r\nN1 G0 X[#1]\r\n";
  for (int i = 0; i < 700; ++i) fanuc += "(FILLER " + std::to_string(i) + ")\r\n";
  fanuc += "#1=#1+1\r\nIF [#1 LT 3] GOTO 1\r\nGOTO 5\r\nN4 G0 X99.\r\n";
  for (int i = 0; i < 300; ++i) fanuc += "(MORE)\r\n";
  fanuc += "N5 G0 Y7.\r\nM98 P9\r\nM30\r\n";
  for (int i = 0; i < 600; ++i) fanuc += "(AFTER)\r\n";
  fanuc += "O9\r\nG0 Z1.\r\nM99";
  std::string heidenhain = "0 BEGIN PGM T MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 CALL LBL 7\n3 CALL LBL 7\n";
  for (int i = 0; i < 900; ++i) heidenhain += "; filler\n";
  heidenhain += "4 END PGM T MM\n5 LBL 7\n6 L IX+2 R0 FMAX\n7 LBL 0";
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ncbridge_streams_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (bool from_file : {false, true}) {
    ncbridge::interpreter::Options options;
    options.dialect = Dialect::Fanuc;
    Collect f;
    Collect h;
    if (from_file) {
      std::ofstream(dir / "long.nc", std::ios::binary) << fanuc;
      std::ofstream(dir / "long.h", std::ios::binary) << heidenhain;
      ncbridge::interpreter::interpret_file(dir / "long.nc", options, f);
      options.dialect = Dialect::Heidenhain;
      ncbridge::interpreter::interpret_file(dir / "long.h", options, h);
    } else {
      f = run(fanuc, Dialect::Fanuc);
      h = run(heidenhain, Dialect::Heidenhain);
    }
    auto e = f.ends();
    ASSERT_EQ(e.size(), 5u) << (from_file ? "file" : "text");
    EXPECT_TRUE(near(e[0], 0, 0, 0));
    EXPECT_TRUE(near(e[1], 1, 0, 0));
    EXPECT_TRUE(near(e[2], 2, 0, 0));
    EXPECT_TRUE(near(e[3], 2, 7, 0));
    EXPECT_TRUE(near(e[4], 2, 7, 1));
    // the source lines of the calls are the file's line numbers: the subprogram's move on line
    // 1612, the program end (M30) on line 1010
    for (const auto& c : f.calls) {
      if (auto* t = std::get_if<ncbridge::canonical::StraightTraverse>(&c.data); t && t->end.z == 1.0) {
        EXPECT_EQ(c.source.line, 3u + 700u + 4u + 300u + 3u + 600u + 2u);
      }
    }
    EXPECT_EQ(f.calls.back().source.line, 1010u);
    auto g = h.ends();
    ASSERT_EQ(g.size(), 3u);
    EXPECT_TRUE(near(g[2], 4, 0, 0));
  }
  std::filesystem::remove_all(dir);
}

// ---- Mach3

TEST(Mach3, ValuesAreTakenAsWrittenAndArcCentresFollowG901) {
  auto sink = run("G21 G90 G0 X10 Y0\nG90.1\nG3 X0 Y10 I0 J0 F100\nM30\n", Dialect::Mach3);
  ASSERT_EQ(sink.calls.empty(), false);
  bool found = false;
  for (const auto& c : sink.calls) {
    if (auto* a = std::get_if<ncbridge::canonical::ArcFeed>(&c.data)) {
      found = true;
      EXPECT_NEAR(a->first_axis, 0.0, 1e-9);
      EXPECT_NEAR(a->second_axis, 0.0, 1e-9);
    }
  }
  EXPECT_TRUE(found);
  auto e = error_of("G21\nWHILE [1] DO 1\n", Dialect::Mach3);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 1u);
}

// ---- SINUMERIK 840D

TEST(Siemens840D, FramesTransAndRot) {
  auto sink = run("G71 G90\nTRANS X10 Y20\nG0 X1 Y0\nAROT RPL=90\nG0 X1 Y0\nTRANS\nG0 X1 Y0\nM30\n", Dialect::Siemens840D);
  auto e = sink.ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_TRUE(near(e[0], 11.0, 20.0, 0.0));
  EXPECT_TRUE(near(e[1], 10.0, 21.0, 0.0));
  EXPECT_TRUE(near(e[2], 1.0, 0.0, 0.0));
}

TEST(Siemens840D, AbsoluteAndIncrementalPerWord) {
  auto sink = run("G71 G91\nG0 X5 Y=AC(7)\nX=AC(1) Y=IC(1)\nM30\n", Dialect::Siemens840D);
  auto e = sink.ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_TRUE(near(e[0], 5.0, 7.0, 0.0));
  EXPECT_TRUE(near(e[1], 1.0, 8.0, 0.0));
}

TEST(Siemens840D, UnsupportedCyclesAreReportedWhereTheyAre) {
  for (const char* cycle : {"SLOT1", "SLOT2", "LONGHOLE"}) {
    auto e = error_of(std::string("G71\nN20 G0 X0 Y0\nN30 ") + cycle + "(10,0,1,-5,,4,20,50,40,30,0,90)\nM30\n",
                      Dialect::Siemens840D);
    EXPECT_EQ(e.where().line, 3u);
    EXPECT_EQ(e.where().column, 5u);
    EXPECT_NE(e.message().find(cycle), std::string::npos) << e.message();
  }
  // a pocket needs the tool's diameter; a helical infeed is not decomposed
  auto e = error_of("G71\nN20 G0 X0 Y0\nN30 POCKET3(10,0,1,-5,40,20,5,0,0,0,1,0.1,0.1,100,100,0,1,5)\nM30\n",
                    Dialect::Siemens840D);
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().column, 5u);
  EXPECT_NE(e.message().find("POCKET3"), std::string::npos);
  EXPECT_NE(e.message().find("diameter"), std::string::npos) << e.message();
  auto h = error_of("G71\nT1 D1 M6\nS1000 M3\nG0 X0 Y0 Z10\nN50 POCKET4(10,0,1,-5,20,0,0,2,0,0,100,100,0,11,5)\nM30\n",
                    with_mill(Dialect::Siemens840D));
  EXPECT_EQ(h.where().line, 5u);
  EXPECT_NE(h.message().find("POCKET4: helical"), std::string::npos) << h.message();
}

TEST(Siemens840D, PocketWithMorePassesThanTheIterationLimitIsAnError) {
  auto options = with_mill(Dialect::Siemens840D);
  options.max_loop_iterations = 1000;
  auto e = error_of("G71\nT1 D1 M6\nS1000 M3\nG0 X0 Y0 Z10\nN50 POCKET4(10,0,1,-5,20,0,0,0.001,0,0,100,100,0,1,0.001)\nM30\n",
                    options);
  EXPECT_EQ(e.where().line, 5u);
  EXPECT_NE(e.message().find("iteration limit"), std::string::npos) << e.message();
}

TEST(Siemens840D, SwivelAndPolarPoleErrorsAreLocated) {
  auto e = error_of("G71\nN20 CYCLE800(1,\"TABLE\",0,57,0,0,0,0,30,0,0,0,0,-1,100,1)\nM30\n", Dialect::Siemens840D);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 5u);
  EXPECT_NE(e.message().find("CYCLE800 swivels the working plane (_B"), std::string::npos) << e.message();
  e = error_of("G71\nN20 G111 AP=30 RP=10\nM30\n", Dialect::Siemens840D);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 5u);
  // no error for a CYCLE800 without rotation or offset
  auto sink = run("G71\nN20 CYCLE800(1,\"TABLE\",0,57,0,0,0,0,0,0,0,0,0,-1,100,1)\nG0 X1\nM30\n", Dialect::Siemens840D);
  EXPECT_EQ(sink.ends().size(), 1u);
}

TEST(Siemens840D, ErrorsAreLocated) {
  auto e = error_of("G71\nG1 X=R1+ F100\nM30\n", Dialect::Siemens840D);
  EXPECT_EQ(e.where().line, 2u);
  e = error_of("G71\nGOTOF NOWHERE\nM30\n", Dialect::Siemens840D);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 1u);
  e = error_of("G71\nG0 X0 Y0\nG2 X10 Y0\nM30\n", Dialect::Siemens840D);
  EXPECT_EQ(e.where().line, 3u);
}

// ---- Heidenhain

TEST(Heidenhain, SectionRepeatRunsTheSectionOnceMoreForEachRep) {
  const std::string program =
      "0 BEGIN PGM T MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 LBL 1\n3 L IX+1 R0 FMAX\n4 CALL LBL 1 REP 2\n5 END PGM T MM\n";
  auto sink = run(program, Dialect::Heidenhain);
  auto e = sink.ends();
  ASSERT_EQ(e.size(), 4u);
  EXPECT_TRUE(near(e[3], 3.0, 0.0, 0.0));
}

TEST(Heidenhain, Cycle9DwellsWhereItIsDefined) {
  const std::string program = "0 BEGIN PGM T MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 CYCL DEF 9.0 DWELL TIME\n"
                              "3 CYCL DEF 9.1 DWELL 1.5\n4 L X+1 R0 FMAX\n5 END PGM T MM\n";
  const auto sink = run(program, Dialect::Heidenhain);
  std::vector<double> dwells;
  for (const auto& c : sink.calls) {
    if (const auto* d = std::get_if<ncbridge::canonical::Dwell>(&c.data)) dwells.push_back(d->seconds);
  }
  ASSERT_EQ(dwells.size(), 1u);
  EXPECT_DOUBLE_EQ(dwells[0], 1.5);
  EXPECT_EQ(sink.ends().size(), 2u);
}

TEST(Heidenhain, ChamferBetweenTwoLines) {
  const std::string program =
      "0 BEGIN PGM T MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 L X+10 F100\n3 CHF 2\n4 L Y+10\n5 END PGM T MM\n";
  auto e = run(program, Dialect::Heidenhain).ends();
  ASSERT_EQ(e.size(), 4u);
  EXPECT_TRUE(near(e[1], 8.0, 0.0, 0.0));
  EXPECT_TRUE(near(e[2], 10.0, 2.0, 0.0));
  EXPECT_TRUE(near(e[3], 10.0, 10.0, 0.0));
}

TEST(Heidenhain, QParameterFunctionsAndLabelCalls) {
  // FN 0-4 (assignment and the four operations), FN 9 jump, a named label called as a subprogram
  const std::string program =
      "0 BEGIN PGM T MM\n1 FN 0: Q1 = +6\n2 FN 3: Q2 = +Q1 * +2.5\n3 FN 4: Q3 = +Q2 DIV +3\n"
      "4 FN 1: Q4 = +Q3 + +Q1\n5 FN 2: Q5 = +Q4 - +20\n6 L X+Q2 Y+Q3 Z+Q5 R0 FMAX\n7 CALL LBL \"MOVE\"\n"
      "8 FN 9: IF +Q3 EQU +5 GOTO LBL 2\n9 L X+99 R0 FMAX\n10 LBL 2\n11 CALL LBL \"MOVE\"\n12 END PGM T MM\n"
      "13 LBL \"MOVE\"\n14 L IX+1 R0 FMAX\n15 LBL 0\n";
  auto e = run(program, Dialect::Heidenhain).ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_TRUE(near(e[0], 15.0, 5.0, -9.0));
  EXPECT_TRUE(near(e[1], 16.0, 5.0, -9.0));
  EXPECT_TRUE(near(e[2], 17.0, 5.0, -9.0));
  auto err = error_of("0 BEGIN PGM T MM\n1 FN 4: Q4 = +1 DIV +Q9\n2 END PGM T MM\n", Dialect::Heidenhain);
  EXPECT_EQ(err.where().line, 2u);
  EXPECT_NE(err.message().find("divide by zero"), std::string::npos) << err.message();
}

TEST(Heidenhain, CallPgmRunsAnotherFileAndComesBack) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("ncbridge_callpgm_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "sub");
  // the called program has its own LBL 1 (the caller's LBL 1 is elsewhere) and calls a third
  std::ofstream(dir / "MAIN.H") << "0 BEGIN PGM MAIN MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 CALL PGM sub\\A.H\n"
                                   "3 CALL PGM A\n4 L X+50 R0 FMAX\n5 END PGM MAIN MM\n6 LBL 1\n7 L X+99 R0 FMAX\n8 LBL 0\n";
  std::ofstream(dir / "sub" / "A.H") << "0 BEGIN PGM A MM\n1 CALL LBL 1\n2 CALL PGM TNC:\\X\\B.H\n3 END PGM A MM\n"
                                        "4 LBL 1\n5 L IX+1 R0 FMAX\n6 LBL 0\n";
  std::ofstream(dir / "sub" / "B.H") << "0 BEGIN PGM B MM\n1 L IY+5 R0 FMAX\n2 END PGM B MM\n";
  std::ofstream(dir / "A.h") << "0 BEGIN PGM A MM\n1 L IX+10 R0 FMAX\n2 END PGM A MM\n";
  ncbridge::interpreter::Options options;
  options.dialect = Dialect::Heidenhain;
  options.subroutine_path = {dir / "sub"};
  Collect sink;
  ncbridge::interpreter::interpret_file(dir / "MAIN.H", options, sink);
  auto e = sink.ends();
  ASSERT_EQ(e.size(), 5u);
  EXPECT_TRUE(near(e[1], 1, 0, 0));   // sub/A.H, its own LBL 1
  EXPECT_TRUE(near(e[2], 1, 5, 0));   // TNC:\\X\\B.H by its file name, beside the calling program
  EXPECT_TRUE(near(e[3], 11, 5, 0));  // A.h beside the main program (A, with .h)
  EXPECT_TRUE(near(e[4], 50, 5, 0));
  std::filesystem::remove_all(dir);
}

TEST(Heidenhain, RoundingBetweenTwoArcs) {
  // circles of radius 10 about (0,0) and (10,10) meet at (0,10) at a right angle; the rounding's
  // centre lies 8 from both centres: (5,5) + sqrt(14) (-1,1)/sqrt(2)
  const std::string program =
      "0 BEGIN PGM T MM\n1 L X+10 Y+0 Z+0 R0 FMAX\n2 CC X+0 Y+0\n3 C X+0 Y+10 DR+ F100\n4 RND R2\n"
      "5 CC X+10 Y+10\n6 C X+10 Y+0 DR+\n7 END PGM T MM\n";
  auto e = run(program, Dialect::Heidenhain).ends();
  ASSERT_EQ(e.size(), 4u);
  const double h = std::sqrt(14.0) / std::sqrt(2.0);
  const double cx = 5 - h, cy = 5 + h;
  EXPECT_TRUE(near(e[1], cx * 1.25, cy * 1.25, 0.0)) << e[1][0] << " " << e[1][1];
  EXPECT_TRUE(near(e[2], 10 + (cx - 10) * 1.25, 10 + (cy - 10) * 1.25, 0.0)) << e[2][0] << " " << e[2][1];
  EXPECT_TRUE(near(e[3], 10.0, 0.0, 0.0));
}

TEST(Heidenhain, CornerAndProgramCallErrorsAreLocated) {
  // the TNC chamfers between two straight lines only
  auto e = error_of("0 BEGIN PGM T MM\n1 L X+0 Y+0 R0 FMAX\n2 CC X+10 Y+0\n3 C X+10 Y+10 DR+ F100\n4 CHF 2\n"
                    "5 L X+20\n6 END PGM T MM\n",
                    Dialect::Heidenhain);
  EXPECT_EQ(e.where().line, 5u);
  EXPECT_EQ(e.where().column, 3u);
  EXPECT_NE(e.message().find("CHF joins two straight lines"), std::string::npos) << e.message();
  e = error_of("0 BEGIN PGM T MM\n1 L X+0 Y+0 R0 FMAX\n2 L X+10 F100\n3 RND R50\n4 L Y+10\n5 END PGM T MM\n",
               Dialect::Heidenhain);
  EXPECT_EQ(e.where().line, 4u);
  EXPECT_NE(e.message().find("too large"), std::string::npos) << e.message();
  e = error_of("0 BEGIN PGM T MM\n1 L X+10 Y+0 R0 FMAX\n2 CC X+0 Y+0\n3 C X+0 Y+10 DR+ F100\n4 RND R2\n"
               "5 CT X+5 Y+20\n6 END PGM T MM\n",
               Dialect::Heidenhain);
  EXPECT_EQ(e.where().line, 5u);
  EXPECT_NE(e.message().find("CT"), std::string::npos) << e.message();
  e = error_of("0 BEGIN PGM T MM\n1 L X+0 R0 FMAX\n2 CALL PGM TNC:\\PARTS\\NOPE.H\n3 END PGM T MM\n",
               Dialect::Heidenhain);
  EXPECT_EQ(e.where().file, "test.prog");
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().column, 3u);
  EXPECT_NE(e.message().find("NOPE.H"), std::string::npos) << e.message();
}

TEST(Heidenhain, ErrorsAreLocated) {
  auto e = error_of("0 BEGIN PGM T MM\n1 L X+0 R0 FMAX\n2 C X+5 Y+5 DR+\n3 END PGM T MM\n", Dialect::Heidenhain);
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().column, 3u);
  EXPECT_NE(e.message().find("CC"), std::string::npos);
  e = error_of("0 BEGIN PGM T MM\n1 L X+0 R0 FMAX\n2 CALL LBL 7\n3 END PGM T MM\n", Dialect::Heidenhain);
  EXPECT_EQ(e.where().line, 3u);
  // found by fuzz_heidenhain: an F without its value in CYCL CALL POS
  e = error_of("0 BEGIN PGM T MM\n1 CYCL DEF 200 DRILLING\n2 CYCL CALL POS X+1 Y+1 Z+2 F\n3 END PGM T MM\n",
               Dialect::Heidenhain);
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().column, 29u);
  EXPECT_NE(e.message().find("F has no value"), std::string::npos) << e.message();
  e = error_of("0 BEGIN PGM T MM\n1 FROB X+0\n2 END PGM T MM\n", Dialect::Heidenhain);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 3u);
  e = error_of("0 BEGIN PGM T MM\n1 L X+0 R0 F100\n2 L X+(Q1 * 2 R0\n3 END PGM T MM\n", Dialect::Heidenhain);
  EXPECT_EQ(e.where().line, 3u);
}

}  // namespace

namespace {

TEST(Siemens840D, StructuredControlErrorsAreLocated) {
  auto e = error_of("G71\nN20 WHILE R1<3\nN30 G0 X1\n", Dialect::Siemens840D);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_NE(e.message().find("ENDWHILE"), std::string::npos);
  e = error_of("G71\nN20 ENDFOR\nM30\n", Dialect::Siemens840D);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 5u);
}

}  // namespace
