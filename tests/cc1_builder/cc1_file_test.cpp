// End to end: programs -> interpreter -> cc1_builder -> Part 21, checked against the ISO 14649
// schema, the paper's appendix A.1, determinism and write -> read -> write identity.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/express_schema.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/schema_check.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

namespace ncbridge::cc1_builder::testing {
namespace {

namespace fs = std::filesystem;
const fs::path kShared = NCBRIDGE_SHARED_DIR;

stepnc::Project build_from(const fs::path& program, const fs::path& tools, const fs::path& stock) {
  Options o;
  o.tools = setup::read_tool_list(tools);
  o.stock = setup::read_stock(stock);
  interpreter::Options io;
  io.tools = o.tools;
  Cc1Builder builder(o);
  interpreter::interpret_file(program, io, builder);
  return builder.take_project();
}

std::string cc1_text(const stepnc::Project& p) {
  step_writer::StepncWriteOptions w;
  w.file_name = "cc1.stp";
  w.unix_time = 1700000000;
  return step_writer::write_stepnc(p, w);
}

const step_writer::express::Schema& schema() {
  static const auto s = step_writer::express::Schema::parse_file(kShared / "reference/iso14649/combined_schema_iso14649_only.exp");
  return s;
}

std::vector<step_writer::Diagnostic> check(const std::string& text, const std::string& name) {
  const auto read = step_writer::part21::read_part21(text, name);
  step_writer::CheckOptions c;
  c.file_name = name;
  c.known_variants_are_warnings = false;
  auto all = step_writer::check_instances(read.graph, schema(), c);
  std::vector<step_writer::Diagnostic> errors;
  for (auto& d : all) if (d.severity == step_writer::Severity::Error) errors.push_back(d);
  return errors;
}

std::string joined(const std::vector<step_writer::Diagnostic>& ds) {
  std::string s;
  for (std::size_t i = 0; i < ds.size() && i < 10; ++i) s += ds[i].to_string() + "\n";
  return s;
}

TEST(Cc1File, FaceMillHasTheEntitiesOfAppendixA1AndItsThirteenPoints) {
  const fs::path paper = kShared / "corpus/paper";
  const auto project = build_from(paper / "face_mill.ngc", paper / "tools.json", paper / "stock.json");
  const std::string text = cc1_text(project);
  const auto graph = step_writer::part21::read_part21(text, "face_mill.stp").graph;
  std::set<std::string> entities;
  for (const auto& i : graph.instances()) entities.insert(i.entity());
  for (const char* e : {"PROJECT", "WORKPLAN", "WORKPIECE", "SETUP", "WORKPIECE_SETUP", "MACHINING_WORKINGSTEP",
                        "RAPID_MOVEMENT", "TOOLPATH_FEATURE", "FREEFORM_OPERATION", "MILLING_CUTTING_TOOL",
                        "ENDMILL", "MILLING_TOOL_DIMENSION", "CUTTING_COMPONENT", "MILLING_TECHNOLOGY",
                        "MILLING_MACHINE_FUNCTIONS", "PLANE", "AXIS2_PLACEMENT_3D", "CARTESIAN_POINT", "DIRECTION",
                        "TOOLPATH_LIST", "CUTTER_LOCATION_TRAJECTORY", "POLYLINE"}) {
    EXPECT_TRUE(entities.count(e)) << e;
  }
  // The freeform operation's toolpath: one POLYLINE with the paper's 13 points.
  const auto ops = graph.ids_of("FREEFORM_OPERATION");
  ASSERT_EQ(ops.size(), 1u);
  const auto& list = graph.at(graph.at(ops[0]).attributes()[0].as_reference());
  const auto& traj = graph.at(list.attributes()[0].as_list().at(0).as_reference());
  const auto& poly = graph.at(traj.attributes()[6].as_reference());
  ASSERT_EQ(poly.entity(), "POLYLINE");
  const std::vector<std::array<double, 3>> expected{
      {91.9, -13.5, 15}, {91.9, -13.5, 0}, {91.9, 133.5, 0}, {74.8, 133.5, 0}, {74.8, -13.5, 0},
      {57.7, -13.5, 0},  {57.7, 133.5, 0}, {40.6, 133.5, 0}, {40.6, -13.5, 0}, {23.5, -13.5, 0},
      {23.5, 133.5, 0},  {6.4, 133.5, 0},  {6.4, -13.5, 0}};
  const auto& pts = poly.attributes()[1].as_list();
  ASSERT_EQ(pts.size(), expected.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& c = graph.at(pts[i].as_reference()).attributes()[1].as_list();
    for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(c[k].as_number(), expected[i][k]) << "point " << i;
  }
  // Technology: 240 mm/min = 0.004 m/s, 720 rpm clockwise = -12 rev/s; flood coolant on.
  const auto& tech = graph.at(graph.ids_of("MILLING_TECHNOLOGY").at(0));
  EXPECT_DOUBLE_EQ(tech.attributes()[0].as_number(), 0.004);
  EXPECT_DOUBLE_EQ(tech.attributes()[3].as_number(), -12);
  EXPECT_EQ(graph.at(graph.ids_of("MILLING_MACHINE_FUNCTIONS").at(0)).attributes()[0].as_enumeration(), "T");
  EXPECT_EQ(check(text, "face_mill.stp").size(), 0u) << joined(check(text, "face_mill.stp"));
}

TEST(Cc1File, SameInputGivesTheSameBytes) {
  const fs::path paper = kShared / "corpus/paper";
  const auto a = cc1_text(build_from(paper / "test_part.ngc", paper / "tools.json", paper / "stock.json"));
  const auto b = cc1_text(build_from(paper / "test_part.ngc", paper / "tools.json", paper / "stock.json"));
  EXPECT_EQ(a, b);
}

TEST(Cc1File, WithSourceDateEpochTwoRunsGiveTheSameBytes) {
  const fs::path paper = kShared / "corpus/paper";
  ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  step_writer::StepncWriteOptions w;  // no explicit time: the writer reads SOURCE_DATE_EPOCH
  w.file_name = "face_mill.stp";
  const auto a = step_writer::write_stepnc(build_from(paper / "face_mill.ngc", paper / "tools.json", paper / "stock.json"), w);
  const auto b = step_writer::write_stepnc(build_from(paper / "face_mill.ngc", paper / "tools.json", paper / "stock.json"), w);
  ::unsetenv("SOURCE_DATE_EPOCH");
  EXPECT_EQ(a, b);
  EXPECT_NE(a.find("'2023-11-14T22:13:20'"), std::string::npos);
}

struct Program {
  fs::path program, tools, stock;
};

std::vector<Program> corpus_programs() {
  std::vector<Program> programs;
  const fs::path paper = kShared / "corpus/paper";
  for (const char* name : {"face_mill.ngc", "test_part.ngc"}) programs.push_back({paper / name, paper / "tools.json", paper / "stock.json"});
  std::vector<fs::path> parts;
  for (const auto& d : fs::directory_iterator(kShared / "corpus/cam")) parts.push_back(d.path());
  std::sort(parts.begin(), parts.end());
  // part.nc is the LinuxCNC post where there is no part.linuxcnc.ngc (else a Fanuc post).
  for (const auto& d : parts) {
    const fs::path program = fs::exists(d / "part.linuxcnc.ngc") ? d / "part.linuxcnc.ngc" : d / "part.nc";
    programs.push_back({program, d / "tools.json", d / "stock.json"});
  }
  return programs;
}

TEST(Cc1File, EveryCorpusProgramGivesASchemaValidFileThatReadsBackIdentically) {
  const auto programs = corpus_programs();
  ASSERT_EQ(programs.size(), 7u);
  for (const auto& p : programs) {
    SCOPED_TRACE(p.program.string());
    const auto project = build_from(p.program, p.tools, p.stock);
    EXPECT_FALSE(project.main_workplan.its_elements.empty());
    const std::string text = cc1_text(project);
    const auto errors = check(text, p.program.filename().string());
    EXPECT_EQ(errors.size(), 0u) << joined(errors);
    const auto back = step_writer::read_stepnc(text, "written.stp");
    EXPECT_TRUE(back.warnings.empty());
    EXPECT_EQ(cc1_text(back.project), text);
  }
}

// Splines (G5 cubic, G5.1 quadratic, G5.2/G5.3 NURBS) are toolpath curves of their own:
// B_SPLINE_CURVE_WITH_KNOTS, and with unequal weights the complex instance with
// RATIONAL_B_SPLINE_CURVE. The file is schema-valid, reads back to the same model and bytes, and
// the curves pass through the points LinuxCNC's NURBS would.
TEST(Cc1File, SplinesAreBSplineCurvesThatReadBack) {
  const fs::path paper = kShared / "corpus/paper";
  Options o;
  o.tools = setup::read_tool_list(paper / "tools.json");
  o.stock = setup::read_stock(paper / "stock.json");
  interpreter::Options io;
  io.tools = o.tools;
  Cc1Builder builder(o);
  interpreter::interpret_text(
      "G21 G90 G17\nT1 M6\nS1000 M3\nG0 X10 Y10 Z5\nG1 Z-1 F300\n"
      "G5 I10 J0 P-10 Q0 X30 Y30\n"               // cubic Bezier (10,10) (20,10) (20,30) (30,30)
      "G5.1 I10 J0 X50 Y50\n"                     // quadratic Bezier (30,30) (40,30) (50,50)
      "G5.2 X60 Y40 P1 L3\nX70 Y50 P1\nX80 Y40 P1\nG5.3\n"  // equal weights: not rational
      "G5.2 X85 Y50 P2\nX90 Y40 P0.5\nX95 Y50 P1\nG5.3\n"   // rational
      "G0 Z5\nM2\n",
      "splines.ngc", io, builder);
  const stepnc::Project project = builder.take_project();
  const std::string text = cc1_text(project);
  EXPECT_EQ(check(text, "splines.stp").size(), 0u) << joined(check(text, "splines.stp"));
  const auto back = step_writer::read_stepnc(text, "splines.stp");
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(cc1_text(back.project), text);

  std::vector<stepnc::BSplineCurve> splines;
  for (const auto& e : back.project.main_workplan.its_elements) {
    const auto* ws = std::get_if<stepnc::MachiningWorkingstep>(&e);
    if (!ws) continue;
    const auto& op = stepnc::machining_operation(back.project.operations.at(ws->its_operation.index));
    for (const auto& t : op.its_toolpath->its_list) {
      for (const auto& seg : t.basiccurve.segments) {
        if (const auto* b = std::get_if<stepnc::BSplineCurve>(&seg)) splines.push_back(*b);
      }
    }
  }
  ASSERT_EQ(splines.size(), 4u);
  // G5: a cubic Bezier; its middle is (P0 + 3 P1 + 3 P2 + P3) / 8, at the cut's depth.
  EXPECT_EQ(splines[0].degree, 3);
  EXPECT_EQ(splines[0].knot_spec, stepnc::KnotType::PiecewiseBezierKnots);
  EXPECT_TRUE(splines[0].weights.empty());
  const auto mid = stepnc::bspline_point(splines[0], 0.5);
  EXPECT_NEAR(mid.x, (10 + 3 * 20 + 3 * 20 + 30) / 8.0, 1e-12);
  EXPECT_NEAR(mid.y, (10 + 3 * 10 + 3 * 30 + 30) / 8.0, 1e-12);
  EXPECT_DOUBLE_EQ(mid.z, -1);
  EXPECT_EQ(splines[1].degree, 2);
  EXPECT_EQ(stepnc::bspline_point(splines[1], 1.0), (stepnc::CartesianPoint{50, 50, -1}));
  // G5.2 with four points of order 3: LinuxCNC's knots 0 0 0 1 2 2 2, i.e. 0 (x3), 1, 2 (x3).
  EXPECT_EQ(splines[2].knots, (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(splines[2].knot_multiplicities, (std::vector<int>{3, 1, 3}));
  EXPECT_EQ(splines[2].knot_spec, stepnc::KnotType::QuasiUniformKnots);
  EXPECT_TRUE(splines[2].weights.empty());
  EXPECT_EQ(splines[3].weights, (std::vector<double>{1, 2, 0.5, 1}));
  EXPECT_EQ(stepnc::bspline_point(splines[3], 2.0), (stepnc::CartesianPoint{95, 50, -1}));
  // At its inner knot the quadratic curve is halfway between control points 1 and 2 (basis
  // functions 1/2 and 1/2), weighted: (2 (85, 50) + 0.5 (90, 40)) / 2.5.
  const auto k1 = stepnc::bspline_point(splines[3], 1.0);
  EXPECT_NEAR(k1.x, (2 * 85 + 0.5 * 90) / 2.5, 1e-12);
  EXPECT_NEAR(k1.y, (2 * 50 + 0.5 * 40) / 2.5, 1e-12);
  EXPECT_NE(text.find("B_SPLINE_CURVE_WITH_KNOTS('',3,"), std::string::npos);
  EXPECT_NE(text.find("=(BOUNDED_CURVE()B_SPLINE_CURVE('',2,"), std::string::npos);  // the complex instance
}

// A program that probes the part (G38.2 down, G38.3 sideways), sets its work offset from the
// result and cuts: the probing moves are WORKPIECE_PROBING workingsteps (touch probing, ISO
// 14649-10), the G38.4 retract is left out with a warning naming its line, the cut converts.
TEST(Cc1File, ProbingIsWorkpieceProbingAndTheCuttingAfterItConverts) {
  const fs::path paper = kShared / "corpus/paper";
  Options o;
  o.tools = setup::read_tool_list(paper / "tools.json");
  o.stock = setup::read_stock(paper / "stock.json");
  interpreter::Options io;
  io.tools = o.tools;
  Cc1Builder builder(o);
  interpreter::interpret_text(
      "G21 G90 G17\nT1 M6\nG0 X10 Y10 Z20\nG38.2 Z-10 F100\nG10 L20 P1 Z0\nG38.4 Z5\n"
      "G0 X-10 Y50 Z-2\nG38.3 X20\nG0 Z20\n"
      "S1000 M3\nG0 X0 Y0\nG1 Z-1 F300\nX50\nY50\nG0 Z20\nM2\n",
      "probing.ngc", io, builder);
  const std::vector<Warning> warnings = builder.warnings();
  const stepnc::Project project = builder.take_project();
  // The offset set from the probe comes after the first motion: the cut is converted into the
  // setup's frame, and said so.
  ASSERT_EQ(warnings.size(), 2u);
  const bool frame_first = warnings[0].message.find("work offset changed") != std::string::npos;
  const Warning& away = warnings[frame_first ? 1 : 0];
  EXPECT_EQ(away.where.line, 6u);
  EXPECT_NE(away.message.find("G38.4"), std::string::npos);
  EXPECT_NE(warnings[frame_first ? 0 : 1].message.find("work offset changed"), std::string::npos);
  const std::string text = cc1_text(project);
  EXPECT_EQ(check(text, "probing.stp").size(), 0u) << joined(check(text, "probing.stp"));
  const auto back = step_writer::read_stepnc(text, "probing.stp");
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(cc1_text(back.project), text);
  std::vector<stepnc::WorkpieceProbing> probings;
  int workingsteps = 0;
  for (const auto& e : back.project.main_workplan.its_elements) {
    if (const auto* w = std::get_if<stepnc::WorkpieceProbing>(&e)) probings.push_back(*w);
    if (std::holds_alternative<stepnc::MachiningWorkingstep>(e)) ++workingsteps;
  }
  ASSERT_EQ(probings.size(), 2u);
  EXPECT_EQ(workingsteps, 1);
  EXPECT_EQ(probings[0].its_direction, (stepnc::Direction{0, 0, -1}));
  EXPECT_DOUBLE_EQ(probings[0].expected_value.theoretical_size, 15);
  EXPECT_EQ(probings[0].measured_offset.its_name, "#5063");
  EXPECT_EQ(probings[0].its_probe, "T1");
  EXPECT_EQ(probings[1].its_direction, (stepnc::Direction{1, 0, 0}));
  EXPECT_NE(text.find("TOUCH_PROBE('T1')"), std::string::npos);
}

}  // namespace
}  // namespace ncbridge::cc1_builder::testing
