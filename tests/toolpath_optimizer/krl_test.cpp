// The KRL writer and its reader: what is written reads back as the same path; what the reader
// does not know is refused with a location.
#include <gtest/gtest.h>

#include <cmath>

#include "ncbridge/common/error.hpp"
#include "ncbridge/toolpath_optimizer/deviation_checker.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"
#include "ncbridge/toolpath_optimizer/krl.hpp"

namespace ncbridge::toolpath_optimizer {
namespace {

Motion line(Vec3 a, Vec3 b, double feed, double e = 0) {
  Motion m;
  m.start = a;
  m.end = b;
  m.feed = feed;
  m.extrusion = e;
  return m;
}

Motion arc(Vec3 a, Vec3 b, double cx, double cy, bool ccw, double feed, double e = 0) {
  Motion m = line(a, b, feed, e);
  m.kind = MotionKind::Arc;
  m.arc.first_centre = cx;
  m.arc.second_centre = cy;
  m.arc.ccw = ccw;
  return m;
}

struct Written {
  std::string src, dat;
};

Written write(std::vector<Element> elements, bool extruder = true) {
  Written w;
  KrlOptions o;
  o.name = "PART";
  o.extruder = extruder;
  KrlWriter writer(o, [&](std::string_view s) { w.src.append(s); }, [&](std::string_view s) { w.dat.append(s); });
  for (auto& e : elements) writer.element(std::move(e));
  writer.end();
  return w;
}

std::vector<PathPiece> read_back(const std::string& src) {
  PathRecorder r;
  read_krl_text(src, "PART.src", r);
  return r.pieces;
}

TEST(Krl, LinesArcsFullCirclesAndExtrusionReadBack) {
  std::vector<Element> in;
  in.push_back({line({0, 0, 0}, {10, 0, 0.2}, 3000)});
  in.push_back({line({10, 0, 0.2}, {20, 0, 0.2}, 1800, 0.4)});
  in.push_back({arc({20, 0, 0.2}, {30, 10, 0.2}, 20, 10, true, 1800, 0.63)});     // a quarter, ccw
  in.push_back({arc({30, 10, 0.2}, {30, 10, 0.2}, 35, 10, false, 1200, 1.2)});   // a full circle, cw
  in.push_back({line({30, 10, 0.2}, {30, 10, 0.2}, 2400, -1.5)});                // a retraction
  const auto w = write(in);
  EXPECT_NE(w.src.find("DEF PART( )"), std::string::npos);
  EXPECT_NE(w.src.find("CIRC "), std::string::npos);
  EXPECT_NE(w.src.find(", CA 360 C_DIS"), std::string::npos);
  EXPECT_NE(w.src.find("$VEL.CP = 0.03\n"), std::string::npos);  // 1800 mm/min
  EXPECT_NE(w.src.find("NCB_FILAMENT(-1.5, 2400)"), std::string::npos);
  EXPECT_NE(w.dat.find("DEFDAT PART PUBLIC"), std::string::npos);
  EXPECT_NE(w.dat.find("DECL GLOBAL REAL NCB_EXTRUDE=0"), std::string::npos);

  PathRecorder expected;
  for (const auto& e : in) expected.element(Element{e});
  // The first move starts from where the program first PTPs to: a PTP, then the path.
  const auto back = read_back(w.src);
  DeviationOptions o;
  o.tolerance = 0.001;
  const auto d = check_deviation(expected.pieces, back, o);
  EXPECT_TRUE(d.passed(0.001)) << d.largest() << (d.problems.empty() ? "" : " " + d.problems.front());
  EXPECT_LT(d.extrusion_error, 1e-5);
}

TEST(Krl, ALoopShiftsTheBaseFrameAndReadsBackRunOut) {
  Loop loop;
  loop.count = 5;
  loop.z_shift = 0.25;
  loop.body.push_back({line({10, 0, 0.2}, {10, 0, 0.4}, 600)});
  loop.body.push_back({arc({10, 0, 0.4}, {10, 0, 0.4}, 0, 0, true, 1800, 2)});
  std::vector<Element> in;
  in.push_back({line({0, 0, 0.2}, {10, 0, 0.2}, 3000)});
  in.push_back({std::move(loop)});
  const auto w = write(in);
  EXPECT_NE(w.src.find("FOR NCB_LAYER = 1 TO 5\n"), std::string::npos) << w.src;
  EXPECT_NE(w.src.find("$BASE = BASE_DATA[1] : NCB_ZOFF"), std::string::npos);
  EXPECT_NE(w.src.find("NCB_ZOFF.Z = NCB_ZOFF.Z + 0.25"), std::string::npos);
  PathRecorder r;
  const auto counts = read_krl_text(w.src, "PART.src", r);
  EXPECT_EQ(counts.loops, 1u);
  EXPECT_EQ(counts.motion_statements, 6u);  // PTP home, PTP start, LIN, (LIN, CIRC) once, PTP home
  ASSERT_EQ(r.pieces.size(), 1u + 10u);
  EXPECT_NEAR(r.pieces.back().end.z, 0.4 + 4 * 0.25, 1e-9);
  EXPECT_EQ(r.pieces.back().kind, MotionKind::Arc);
  EXPECT_NEAR(r.pieces.back().extrusion, 2, 1e-5);
}

TEST(Krl, ModuleNames) {
  EXPECT_EQ(krl_module_name("cylinder"), "CYLINDER");
  EXPECT_EQ(krl_module_name("my part-v2.final"), "MY_PART_V2_FINAL");
  EXPECT_EQ(krl_module_name("3dp"), "P3DP");
  EXPECT_EQ(krl_module_name("a_very_long_name_of_a_program_file").size(), 24u);
}

TEST(Krl, WhatTheReaderDoesNotReadIsLocated) {
  auto error = [](const std::string& src) {
    PathRecorder r;
    try {
      read_krl_text(src, "x.src", r);
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no error for: " << src;
    return InputError({}, "");
  };
  auto e = error("DEF X( )\n  PTP {X 0, Y 0, Z 0}\n  SPLINE\nEND\n");
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().column, 3u);
  e = error("DEF X( )\n  LIN {X 1, Y 2, Z 3}\nEND\n");  // from nowhere
  EXPECT_NE(e.message().find("not known"), std::string::npos);
  e = error("DEF X( )\n  PTP {X 0, Y 0, Z 0}\n  LIN {X 1, Y 2, Q 3}\nEND\n");
  EXPECT_NE(e.message().find("component Q"), std::string::npos);
  e = error("DEF X( )\n  PTP {X 0, Y 0, Z 0}\n  LIN {X 1,, Y 2}\nEND\n");
  EXPECT_EQ(e.where().line, 3u);
  e = error("DEF X( )\n  FOR I = 1 TO 3\n  PTP NCB_HOME\nEND\n");
  EXPECT_NE(e.message().find("FOR without ENDFOR"), std::string::npos);
  e = error("DEF X( )\n  PTP {X 0, Y 0, Z 0}\n  CIRC {X 1, Y 1, Z 0}, {X 2, Y 2, Z 0}\nEND\n");
  EXPECT_NE(e.message().find("on a line"), std::string::npos);
  e = error("DEF X( )\n  PTP {X 0, Y 0, Z 0}\n");
  EXPECT_NE(e.message().find("DEF without END"), std::string::npos);
}

}  // namespace
}  // namespace ncbridge::toolpath_optimizer
