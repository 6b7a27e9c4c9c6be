// The writer's own constructs through the public API: the repeat construct read back as the
// unrolled motion in every dialect, text conventions of each dialect, and located refusals.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "ncbridge/common/error.hpp"
#include "ncbridge/gcode_writer/program_writer.hpp"
#include "ncbridge/gcode_writer/stepnc_interpreter.hpp"
#include "ncbridge/interpreter/canon_printer.hpp"
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
