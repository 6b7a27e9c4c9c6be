// The writer's own constructs through the public API: the repeat construct read back as the
// unrolled motion in every dialect, text conventions of each dialect, and located refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <cstdlib>

#include "ncbridge/common/error.hpp"
#include "ncbridge/gcode_writer/program_writer.hpp"
#include "ncbridge/gcode_writer/stepnc_interpreter.hpp"
#include "ncbridge/interpreter/canon_printer.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "support/listing.hpp"
#include "support/same_motion.hpp"

using namespace ncbridge;
using namespace ncbridge::canonical;

namespace {

const gcode_writer::Dialect kDialects[] = {gcode_writer::Dialect::Rs274Ngc, gcode_writer::Dialect::Fanuc,
                                           gcode_writer::Dialect::Mach3, gcode_writer::Dialect::Siemens840D,
                                           gcode_writer::Dialect::Heidenhain};

interpreter::Dialect reader_of(gcode_writer::Dialect d) {
  switch (d) {
    case gcode_writer::Dialect::Fanuc: return interpreter::Dialect::Fanuc;
    case gcode_writer::Dialect::Mach3: return interpreter::Dialect::Mach3;
    case gcode_writer::Dialect::Siemens840D: return interpreter::Dialect::Siemens840D;
    case gcode_writer::Dialect::Heidenhain: return interpreter::Dialect::Heidenhain;
    case gcode_writer::Dialect::Rs274Ngc: break;
  }
  return interpreter::Dialect::Rs274Ngc;
}

Call at(Data d, std::uint32_t line = 1) { return Call{std::move(d), Source{0, line, -1, 0}, std::nullopt}; }

Pose xyz(double x, double y, double z) {
  Pose p;
  p.x = x;
  p.y = y;
  p.z = z;
  return p;
}

// The listing of calls, as `ncbridge canon` prints them.
std::string listing(const std::vector<Call>& calls) {
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* memory = open_memstream(&buffer, &size);
  {
    interpreter::CanonPrinter printer(memory);
    for (const Call& c : calls) printer.call(c);
    printer.flush();
  }
  std::fclose(memory);
  std::string text(buffer, size);
  std::free(buffer);
  return text;
}

std::vector<Call> start_up() {
  return {at(UseLengthUnits{Units::Millimeters}), at(SetG5xOffset{1, Pose{}}), at(SetG92Offset{Pose{}}),
          at(SetXyRotation{0}), at(SetFeedReference{FeedReference::Xyz}), at(OnReset{})};
}

std::string read_back(const std::string& text, gcode_writer::Dialect d) {
  interpreter::Options o;
  o.dialect = reader_of(d);
  return ncbridge::testing::canon_listing_of_text(text, "written" + std::string(gcode_writer::program_extension(d)), o);
}

// One layer of a pocket: plunge by the step, a square with a rounded corner, back to the start.
std::vector<Call> layer(double z) {
  return {at(StraightFeed{xyz(10, 10, z)}),       at(StraightFeed{xyz(30, 10, z)}),
          at(StraightFeed{xyz(30, 25, z)}),       at(ArcFeed{25, 30, 25, 25, 1, z, 0, 0, 0, 0, 0, 0}),
          at(StraightFeed{xyz(10, 30, z)}),       at(StraightFeed{xyz(10, 10, z)})};
}

TEST(RepeatConstruct, ReadsBackAsEveryCopyInEveryDialect) {
  for (gcode_writer::Dialect d : kDialects) {
    SCOPED_TRACE(std::string(gcode_writer::dialect_name(d)));
    gcode_writer::Options options;
    options.dialect = d;
    std::string text;
    std::vector<Call> expected = start_up();
    {
      gcode_writer::ProgramWriter writer(options, [&](std::string_view piece) { text.append(piece); });
      for (const Call& c : start_up()) writer.call(c);
      const std::vector<Call> head = {at(SetSpindleSpeed{0, 3000}), at(StartSpindleClockwise{0}),
                                      at(StraightTraverse{xyz(10, 10, 5)}), at(StraightTraverse{xyz(10, 10, 0)}),
                                      at(SetFeedRate{400})};
      for (const Call& c : head) {
        writer.call(c);
        expected.push_back(c);
      }
      writer.begin_repeat(4, -1.5);
      for (const Call& c : layer(-1.5)) writer.call(c);
      writer.end_repeat();
      for (int copy = 0; copy < 4; ++copy) {
        for (const Call& c : layer(-1.5 * (copy + 1))) expected.push_back(c);
      }
      const std::vector<Call> tail = {at(StraightTraverse{xyz(10, 10, 5)}), at(ProgramEnd{})};
      for (const Call& c : tail) {
        writer.call(c);
        expected.push_back(c);
      }
      writer.end();
    }
    const auto comparison = ncbridge::testing::compare_motion(listing(expected), read_back(text, d));
    EXPECT_TRUE(comparison.equal) << comparison.report << "\n" << text;
    EXPECT_GT(comparison.actions, 25u);
  }
}

TEST(RepeatConstruct, ABodyThatDoesNotJoinUpIsRefused) {
  for (gcode_writer::Dialect d : kDialects) {
    gcode_writer::Options options;
    options.dialect = d;
    gcode_writer::ProgramWriter writer(options, [](std::string_view) {});
    writer.call(at(SetFeedRate{100}));
    writer.call(at(StraightTraverse{xyz(0, 0, 1)}));
    writer.begin_repeat(3, -1);
    writer.call(at(StraightFeed{xyz(5, 0, 0)}, 7));
    EXPECT_THROW(writer.end_repeat(), InputError);
  }
}

TEST(RepeatConstruct, OnlyMovesRepeat) {
  gcode_writer::Options options;
  gcode_writer::ProgramWriter writer(options, [](std::string_view) {});
  writer.begin_repeat(2, -1);
  try {
    writer.call(at(StartSpindleClockwise{0}, 12));
    FAIL() << "a spindle start inside a repeated body was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 12u);
    EXPECT_NE(std::string(e.what()).find("repeated body"), std::string::npos) << e.what();
  }
}

TEST(Dialects, FanucNumbersCarryADecimalPoint) {
  gcode_writer::Options options;
  options.dialect = gcode_writer::Dialect::Fanuc;
  std::vector<Call> calls = start_up();
  calls.push_back(at(StraightTraverse{xyz(10, 2.5, 30)}));
  calls.push_back(at(ProgramEnd{}));
  const std::string text = gcode_writer::write_program(calls, options);
  EXPECT_NE(text.find("X10. Y2.5 Z30."), std::string::npos) << text;
  EXPECT_NE(text.find("O1000"), std::string::npos) << text;
  EXPECT_EQ(text.rfind("%\n"), text.size() - 2) << text;
}

TEST(Dialects, APathToleranceIsNotReadAsAnArcsTurns) {
  // G64 P0.1 on the block of a G2 would be its P (turns): the mode goes on a block of its own.
  gcode_writer::Options options;
  std::vector<Call> calls = start_up();
  calls.push_back(at(StraightTraverse{xyz(0, 0, 0)}));
  calls.push_back(at(SetFeedRate{300}));
  calls.push_back(at(SetMotionControlMode{MotionControlMode::Continuous, 0.1}));
  calls.push_back(at(SetNaivecamTolerance{0.01}));
  calls.push_back(at(ArcFeed{10, 0, 5, 0, -1, 0, 0, 0, 0, 0, 0, 0}));
  calls.push_back(at(ProgramEnd{}));
  const std::string text = gcode_writer::write_program(calls, options);
  const auto arc = text.find("G2 ");
  ASSERT_NE(arc, std::string::npos) << text;
  EXPECT_EQ(text.substr(text.rfind('\n', arc) + 1, text.find('\n', arc) - text.rfind('\n', arc)).find('P'), std::string::npos)
      << text;
  EXPECT_NE(text.find("G64 P0.1 Q0.01"), std::string::npos) << text;
  EXPECT_NO_THROW(read_back(text, gcode_writer::Dialect::Rs274Ngc)) << text;
}

TEST(Refusals, NameTheConstructTheDialectAndTheSourceLine) {
  gcode_writer::Options options;
  options.dialect = gcode_writer::Dialect::Fanuc;
  gcode_writer::ProgramWriter writer(options, [](std::string_view) {});
  writer.source_file(0, "part.ngc");
  writer.call(at(SetSpindleMode{0, 2500}, 3));
  writer.call(at(SetFeedRate{100}, 3));
  try {
    writer.call(at(StraightFeed{xyz(1, 0, 0)}, 4));
    FAIL() << "fanuc wrote constant surface speed";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "part.ngc");
    EXPECT_EQ(e.where().line, 4u);
    EXPECT_NE(std::string(e.what()).find("fanuc cannot express constant surface speed"), std::string::npos) << e.what();
  }
}

// A CC1 project made in memory (as the toolpath generator will hand one over).
stepnc::Project one_cut_project() {
  stepnc::Project p;
  stepnc::MillingCuttingTool tool;
  tool.its_id = "T4 END MILL";
  tool.number = 4;
  tool.dimension.diameter = 10;
  tool.tool_offset_length = 60;
  p.tools.push_back(tool);
  stepnc::MillingTechnology tech;
  tech.feedrate = 0.01;  // 600 mm/min
  tech.spindle = -50;    // 3000 rpm clockwise
  p.technologies.push_back(tech);
  p.machine_functions.push_back({});
  stepnc::ToolpathFeature feature;
  feature.its_id = "TOOLPATH FEATURE1";
  p.features.push_back(feature);
  stepnc::FreeformOperation op;
  op.its_id = "CUT";
  stepnc::CutterLocationTrajectory path;
  path.basiccurve.segments.push_back(stepnc::Polyline{{{0, 0, 5}, {0, 0, -1}, {20, 0, -1}}});
  op.its_toolpath = stepnc::ToolpathList{{path}};
  p.operations.push_back(op);
  stepnc::MachiningWorkingstep ws;
  ws.its_id = "WS CUT";
  ws.its_secplane.position.location.z = 10;
  p.main_workplan.its_elements.push_back(ws);
  return p;
}

TEST(StepncInterpreter, AProjectInMemoryIsWrittenAndReadsBack) {
  const stepnc::Project project = one_cut_project();
  for (gcode_writer::Dialect d : kDialects) {
    SCOPED_TRACE(std::string(gcode_writer::dialect_name(d)));
    gcode_writer::Options options;
    options.dialect = d;
    options.tools = gcode_writer::stepnc_tools(project);
    std::string text;
    {
      gcode_writer::ProgramWriter writer(options, [&](std::string_view piece) { text.append(piece); });
      gcode_writer::interpret_stepnc(project, "memory.stp", {}, writer);
    }
    interpreter::Options back;
    back.dialect = reader_of(d);
    back.tools = options.tools;
    const std::string listing = ncbridge::testing::canon_listing_of_text(text, "p", back);
    // above the start at the security plane, down to it, the cut at 600 mm/min and 3000 rpm
    EXPECT_NE(listing.find("STRAIGHT_TRAVERSE(0.0000, 0.0000, 10.0000"), std::string::npos) << listing;
    EXPECT_NE(listing.find("SET_FEED_RATE(600.0000)"), std::string::npos) << listing;
    EXPECT_NE(listing.find("SET_SPINDLE_SPEED(0, 3000.0000)"), std::string::npos) << listing;
    EXPECT_NE(listing.find("STRAIGHT_FEED(20.0000, 0.0000, -1.0000"), std::string::npos) << listing;
    EXPECT_NE(listing.find("USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 60.0000"), std::string::npos) << listing;
  }
}

TEST(StepncInterpreter, ACc2OperationWithoutToolpathIsALocatedError) {
  stepnc::Project project = one_cut_project();
  stepnc::PlaneRoughMilling rough;
  rough.its_id = "ROUGH";
  project.operations[0] = rough;
  gcode_writer::ProgramWriter writer(gcode_writer::Options{}, [](std::string_view) {});
  try {
    gcode_writer::interpret_stepnc(project, "cc2.stp", {}, writer);
    FAIL() << "a CC2 operation without toolpath was written";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "cc2.stp");
    EXPECT_EQ(e.where().line, 1u);
    EXPECT_NE(std::string(e.what()).find("WS CUT"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("PLANE_ROUGH_MILLING without an explicit toolpath"), std::string::npos) << e.what();
  }
}

TEST(StepncInterpreter, ToolpathsFollowTheFeaturePlacementOrTheSetup) {
  stepnc::Project project = one_cut_project();
  auto& feature = std::get<stepnc::ToolpathFeature>(project.features[0]);
  feature.feature_placement.location = {100, 50, 0};
  for (const auto frame : {gcode_writer::StepncOptions::ToolpathFrame::Feature, gcode_writer::StepncOptions::ToolpathFrame::Setup}) {
    gcode_writer::StepncOptions options;
    options.toolpath_frame = frame;
    struct Last final : canonical::Sink {
      canonical::Pose end;
      void call(const canonical::Call& c) override {
        if (const auto* f = std::get_if<canonical::StraightFeed>(&c.data)) end = f->end;
      }
    } last;
    gcode_writer::interpret_stepnc(project, "p.stp", options, last);
    EXPECT_DOUBLE_EQ(last.end.x, frame == gcode_writer::StepncOptions::ToolpathFrame::Feature ? 120 : 20);
    EXPECT_DOUBLE_EQ(last.end.y, frame == gcode_writer::StepncOptions::ToolpathFrame::Feature ? 50 : 0);
  }
}

}  // namespace

namespace {

struct Collect final : canonical::Sink {
  std::vector<Call> calls;
  void call(const Call& c) override { calls.push_back(c); }
};

std::vector<Call> calls_of_file(const std::filesystem::path& program, interpreter::Dialect dialect) {
  interpreter::Options o;
  o.dialect = dialect;
  Collect c;
  interpreter::interpret_file(program, o, c);
  return c.calls;
}

std::vector<Call> calls_of_text(const std::string& text, interpreter::Dialect dialect) {
  interpreter::Options o;
  o.dialect = dialect;
  Collect c;
  interpreter::interpret_text(text, "written", o, c);
  return c.calls;
}

bool near(const Pose& a, const Pose& b, double tolerance) {
  return std::fabs(a.x - b.x) <= tolerance && std::fabs(a.y - b.y) <= tolerance && std::fabs(a.z - b.z) <= tolerance &&
         std::fabs(a.a - b.a) <= tolerance && std::fabs(a.b - b.b) <= tolerance && std::fabs(a.c - b.c) <= tolerance;
}

template <class T>
std::vector<T> only(const std::vector<Call>& calls) {
  std::vector<T> found;
  for (const Call& c : calls) {
    if (const auto* t = std::get_if<T>(&c.data)) found.push_back(*t);
  }
  return found;
}

const std::filesystem::path kGolden = std::filesystem::path(NCBRIDGE_SOURCE_DIR) / "tests/interpreter/golden/programs";
const std::filesystem::path kDialectPrograms = std::filesystem::path(NCBRIDGE_SOURCE_DIR) / "tests/interpreter/dialects";

}  // namespace

// The listings print a NURBS_FEED as its order only: the control points and weights are compared
// here, call by call (G5 cubic, G5.1 quadratic, G5.2 with weights, a first weight alone, L, G91,
// inches), as G5.2/G5.3 written back.
TEST(Splines, NurbsCurvesReadBackControlPointForControlPoint) {
  const auto source = calls_of_file(kGolden / "splines_g5_nurbs.ngc", interpreter::Dialect::Rs274Ngc);
  gcode_writer::Options options;
  const std::string text = gcode_writer::write_program(source, options);
  const auto back = calls_of_text(text, interpreter::Dialect::Rs274Ngc);
  const auto a = only<NurbsFeed>(source), b = only<NurbsFeed>(back);
  ASSERT_EQ(a.size(), 9u);
  ASSERT_EQ(a.size(), b.size()) << text;
  for (std::size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE("curve " + std::to_string(i));
    EXPECT_EQ(a[i].order, b[i].order);
    ASSERT_EQ(a[i].control_points.size(), b[i].control_points.size()) << text;
    for (std::size_t k = 0; k < a[i].control_points.size(); ++k) {
      EXPECT_NEAR(a[i].control_points[k].x, b[i].control_points[k].x, 1e-4);
      EXPECT_NEAR(a[i].control_points[k].y, b[i].control_points[k].y, 1e-4);
      EXPECT_NEAR(a[i].control_points[k].weight, b[i].control_points[k].weight, 1e-6);
    }
  }
  const auto motion = ncbridge::testing::compare_motion(listing(source), listing(back));
  EXPECT_TRUE(motion.equal) << motion.report;
  EXPECT_NE(text.find("G5.2 P2\n"), std::string::npos) << text;  // the first control point's weight alone
  EXPECT_NE(text.find(" L4"), std::string::npos) << text;
  // the other dialects' front-ends read no splines
  for (gcode_writer::Dialect d : kDialects) {
    if (d == gcode_writer::Dialect::Rs274Ngc) continue;
    options.dialect = d;
    try {
      gcode_writer::write_program(source, options);
      ADD_FAILURE() << gcode_writer::dialect_name(d) << " wrote a NURBS curve";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("cannot express a NURBS curve"), std::string::npos) << e.what();
      EXPECT_EQ(e.where().line, 7u) << e.what();  // the first G5
    }
  }
}

// Probe moves keep their kind (G38.2-G38.5 in RS274/NGC; G31 and MEAS= are G38.3, MEAS=-1 is
// G38.5) and the reader stands where its simulated probe backed off to, as the source's did.
TEST(Probing, ProbeMovesReadBackAsTheSameKindInEveryDialectThatHasThem) {
  const auto golden = calls_of_file(kGolden / "probing_g38.ngc", interpreter::Dialect::Rs274Ngc);
  const auto skip = calls_of_file(kDialectPrograms / "fanuc/skip_probing.nc", interpreter::Dialect::Fanuc);
  const auto meas = calls_of_file(kDialectPrograms / "siemens840d/measuring.mpf", interpreter::Dialect::Siemens840D);
  struct Case {
    const std::vector<Call>* source;
    gcode_writer::Dialect to;
  };
  const Case cases[] = {{&golden, gcode_writer::Dialect::Rs274Ngc},   {&skip, gcode_writer::Dialect::Rs274Ngc},
                        {&skip, gcode_writer::Dialect::Fanuc},        {&skip, gcode_writer::Dialect::Mach3},
                        {&skip, gcode_writer::Dialect::Siemens840D},  {&meas, gcode_writer::Dialect::Siemens840D},
                        {&meas, gcode_writer::Dialect::Rs274Ngc}};
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(gcode_writer::dialect_name(c.to)));
    gcode_writer::Options options;
    options.dialect = c.to;
    const std::string text = gcode_writer::write_program(*c.source, options);
    const auto back = calls_of_text(text, reader_of(c.to));
    const auto a = only<StraightProbe>(*c.source), b = only<StraightProbe>(back);
    ASSERT_FALSE(a.empty());
    ASSERT_EQ(a.size(), b.size()) << text;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].probe_type, b[i].probe_type) << "probe " << i << "\n" << text;
      EXPECT_TRUE(near(a[i].end, b[i].end, 1e-4)) << "probe " << i << "\n" << text;
    }
    const auto motion = ncbridge::testing::compare_motion(listing(*c.source), listing(back));
    EXPECT_TRUE(motion.equal) << motion.report << "\n" << text;
  }
  // what a dialect's probe move is not
  const std::pair<gcode_writer::Dialect, std::string> refused[] = {
      {gcode_writer::Dialect::Fanuc, "fanuc cannot express a probe move that stops with an error when the probe does not trip (G38.2)"},
      {gcode_writer::Dialect::Siemens840D, "siemens840d cannot express a probe move that stops with an error"}};
  for (const auto& [d, message] : refused) {
    gcode_writer::Options options;
    options.dialect = d;
    try {
      gcode_writer::write_program(golden, options);
      ADD_FAILURE() << gcode_writer::dialect_name(d) << " wrote G38.2";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
      EXPECT_EQ(e.where().line, 8u) << e.what();
    }
  }
}

// A WORKPIECE_PROBING of a CC1 model (between two cuts, the feed of the first in effect): to
// its start over the security plane, a G38.2 over the expected travel (nominal + upper limit)
// with the probe on, and the path after it goes on from where the probe stopped (no connecting
// move back to the trip point). G38.2 is RS274/NGC's: the writers without it refuse it by name.
TEST(StepncInterpreter, AWorkpieceProbingIsAProbeMove) {
  stepnc::Project project = one_cut_project();
  stepnc::WorkpieceProbing probing;
  probing.its_id = "PROBING1";
  probing.its_secplane.position.location.z = 10;
  probing.start_position.location = {20, 0, 5};
  probing.its_direction = {0, 0, -2};
  probing.expected_value.theoretical_size = 10;
  probing.expected_value.upper_limit = 10;
  probing.expected_value.lower_limit = 10;
  probing.its_probe = "T4";
  stepnc::FreeformOperation after = std::get<stepnc::FreeformOperation>(project.operations[0]);
  after.its_id = "AFTER";
  stepnc::CutterLocationTrajectory path;
  path.basiccurve.segments.push_back(stepnc::Polyline{{{20, 0, -15}, {40, 0, -15}}});
  after.its_toolpath = stepnc::ToolpathList{{path}};
  project.operations.push_back(after);
  stepnc::MachiningWorkingstep ws2 = std::get<stepnc::MachiningWorkingstep>(project.main_workplan.its_elements[0]);
  ws2.its_id = "WS AFTER";
  ws2.its_operation.index = 1;
  project.main_workplan.its_elements.push_back(probing);
  project.main_workplan.its_elements.push_back(ws2);
  gcode_writer::Options options;
  options.tools = gcode_writer::stepnc_tools(project);
  Collect calls;
  gcode_writer::interpret_stepnc(project, "probe.stp", {}, calls);
  const auto probes = only<StraightProbe>(calls.calls);
  ASSERT_EQ(probes.size(), 1u);
  EXPECT_EQ(probes[0].probe_type, 0);
  EXPECT_TRUE(near(probes[0].end, xyz(20, 0, -15), 1e-9));
  std::size_t probe_at = 0;
  for (std::size_t i = 0; i < calls.calls.size(); ++i) {
    if (std::holds_alternative<StraightProbe>(calls.calls[i].data)) probe_at = i;
  }
  ASSERT_GT(probe_at, 0u);
  EXPECT_TRUE(std::holds_alternative<TurnProbeOn>(calls.calls[probe_at - 1].data));
  ASSERT_LT(probe_at + 1, calls.calls.size());
  EXPECT_TRUE(std::holds_alternative<TurnProbeOff>(calls.calls[probe_at + 1].data));
  for (std::size_t i = probe_at; i < calls.calls.size(); ++i) {
    EXPECT_FALSE(std::holds_alternative<StraightTraverse>(calls.calls[i].data)) << "a move back to the trip point";
  }
  const std::string text = gcode_writer::write_program(calls.calls, options);
  EXPECT_NE(text.find("G38.2 Z-15"), std::string::npos) << text;
  // read back: the same probe move, and the next cut straight from where the probe stopped
  const auto back = calls_of_text(text, interpreter::Dialect::Rs274Ngc);
  const auto back_probes = only<StraightProbe>(back);
  ASSERT_EQ(back_probes.size(), 1u) << text;
  EXPECT_EQ(back_probes[0].probe_type, 0);
  EXPECT_TRUE(near(back_probes[0].end, xyz(20, 0, -15), 1e-9)) << text;
  const auto feeds = only<StraightFeed>(back);
  ASSERT_FALSE(feeds.empty());
  EXPECT_TRUE(near(feeds.back().end, xyz(40, 0, -15), 1e-9)) << text;
  EXPECT_EQ(only<StraightTraverse>(back).size(), only<StraightTraverse>(calls.calls).size()) << text;
  // Fanuc's G31 goes on without an alarm when nothing trips it: not the G38.2 the model asks for
  options.dialect = gcode_writer::Dialect::Fanuc;
  try {
    gcode_writer::write_program(calls.calls, options);
    ADD_FAILURE() << "fanuc wrote G38.2";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fanuc cannot express a probe move that stops with an error"), std::string::npos)
        << e.what();
  }
}

// A probing with no travel is a located error naming the element; one before the first cut
// (no feed yet: ISO 14649 gives WORKPIECE_PROBING none) probes at 100 mm/min, said in a comment.
TEST(StepncInterpreter, AProbingWithoutTravelIsALocatedErrorWithoutFeedIsAt100) {
  for (const bool no_travel : {false, true}) {
    stepnc::Project project = one_cut_project();
    stepnc::WorkpieceProbing probing;
    probing.its_id = "PROBING1";
    probing.start_position.location = {0, 0, 5};
    probing.its_direction = {0, 0, -1};
    probing.expected_value.theoretical_size = no_travel ? 0 : 10;
    if (no_travel) {
      project.main_workplan.its_elements.push_back(probing);
    } else {
      project.main_workplan.its_elements.insert(project.main_workplan.its_elements.begin(), probing);
    }
    Collect calls;
    try {
      gcode_writer::interpret_stepnc(project, "probe.stp", {}, calls);
      EXPECT_FALSE(no_travel) << "a probing with no travel was written";
      std::vector<double> feeds;
      for (const Call& c : calls.calls) {
        if (const auto* f = std::get_if<SetFeedRate>(&c.data)) feeds.push_back(f->rate);
        if (std::holds_alternative<StraightProbe>(c.data)) break;
      }
      ASSERT_FALSE(feeds.empty());
      EXPECT_DOUBLE_EQ(feeds.back(), 100);
    } catch (const InputError& e) {
      EXPECT_TRUE(no_travel) << e.what();
      EXPECT_EQ(e.where().file, "probe.stp");
      EXPECT_NE(std::string(e.what()).find("PROBING1"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("no travel"), std::string::npos) << e.what();
    }
  }
}

// Fanuc's additional work offset (G54.1 Pn, read as coordinate system 9) is written back as
// G54.1 P1 with its values by G10 L20 P1; SINUMERIK's CYCLE832 (read as G64 P) as CYCLE832.
TEST(Dialects, FanucAdditionalOffsetAndSinumerikTolerance) {
  const auto fanuc = calls_of_file(kDialectPrograms / "fanuc/macro_shop.nc", interpreter::Dialect::Fanuc);
  gcode_writer::Options options;
  options.dialect = gcode_writer::Dialect::Fanuc;
  const std::string nc = gcode_writer::write_program(fanuc, options);
  EXPECT_NE(nc.find("G10 L20 P1 X"), std::string::npos) << nc;
  EXPECT_NE(nc.find("G54.1 P1"), std::string::npos) << nc;
  const auto nc_back = calls_of_text(nc, interpreter::Dialect::Fanuc);
  const auto nc_motion = ncbridge::testing::compare_motion(listing(fanuc), listing(nc_back));
  EXPECT_TRUE(nc_motion.equal) << nc_motion.report << "\n" << nc;
  options.dialect = gcode_writer::Dialect::Mach3;
  EXPECT_THROW(gcode_writer::write_program(fanuc, options), InputError);  // Mach3 has no G54.1

  const auto siemens = calls_of_file(kDialectPrograms / "siemens840d/shop_program.mpf", interpreter::Dialect::Siemens840D);
  options.dialect = gcode_writer::Dialect::Siemens840D;
  const std::string mpf = gcode_writer::write_program(siemens, options);
  EXPECT_NE(mpf.find("CYCLE832(0.02,0,1)"), std::string::npos) << mpf;
  const auto mpf_back = calls_of_text(mpf, interpreter::Dialect::Siemens840D);
  const auto mpf_motion = ncbridge::testing::compare_motion(listing(siemens), listing(mpf_back));
  EXPECT_TRUE(mpf_motion.equal) << mpf_motion.report;
}

// Heidenhain's TCH PROBE 0 written back: the pre-position rapid, the probe move over the
// measuring range at the probing feed and the rapid back are one cycle (0.0 axis and direction,
// 0.1 the pre-position); a probe move without the rapid back is refused at its own line.
TEST(Probing, HeidenhainTouchProbeCycleIsWrittenBack) {
  interpreter::Options reading;
  reading.dialect = interpreter::Dialect::Heidenhain;
  reading.tools = setup::read_tool_list(kDialectPrograms / "parts/tools.json");
  Collect read;
  interpreter::interpret_file(kDialectPrograms / "heidenhain/touch_probe.h", reading, read);
  const auto& source = read.calls;
  gcode_writer::Options options;
  options.dialect = gcode_writer::Dialect::Heidenhain;
  options.tools = reading.tools;
  const std::string text = gcode_writer::write_program(source, options);
  EXPECT_NE(text.find("TCH PROBE 0.0 REF. PLANE Q1999 Z-\n"), std::string::npos) << text;
  EXPECT_NE(text.find("TCH PROBE 0.1 X+15 Y+25 Z+5\n"), std::string::npos) << text;
  EXPECT_NE(text.find("TCH PROBE 0.0 REF. PLANE Q1999 X+\n"), std::string::npos) << text;
  Collect back_calls;
  interpreter::interpret_text(text, "written", reading, back_calls);
  const auto& back = back_calls.calls;
  EXPECT_EQ(only<StraightProbe>(back).size(), 2u);
  const auto motion = ncbridge::testing::compare_motion(listing(source), listing(back));
  EXPECT_TRUE(motion.equal) << motion.report << "\n" << text;

  const auto skip = calls_of_file(kDialectPrograms / "fanuc/skip_probing.nc", interpreter::Dialect::Fanuc);
  try {
    gcode_writer::write_program(skip, options);
    ADD_FAILURE() << "heidenhain wrote a G31 without the return";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("heidenhain cannot express a probe move not followed by a rapid back"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.where().line, 7u) << e.what();
  }
}
