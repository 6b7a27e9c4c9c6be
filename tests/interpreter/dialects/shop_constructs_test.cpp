// Constructs of real shop programs (issue 20) through the library API, each with its canonical
// result worked out by hand: G43 without tool lengths, Mach3 `;` comments, Heidenhain blocks of
// M functions, `~` continuation, comma decimals, FN 18, cycle 32; errors and warnings located.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace {

using ncbridge::InputError;
using ncbridge::SourceLocation;
using ncbridge::canonical::Call;
using ncbridge::interpreter::Dialect;
using ncbridge::interpreter::Options;
namespace canonical = ncbridge::canonical;

class Collect final : public canonical::Sink {
 public:
  void call(const Call& c) override { calls.push_back(c); }
  std::vector<Call> calls;
  std::vector<std::array<double, 3>> ends() const {
    std::vector<std::array<double, 3>> out;
    for (const auto& c : calls) {
      if (auto* f = std::get_if<canonical::StraightFeed>(&c.data)) out.push_back({f->end.x, f->end.y, f->end.z});
      if (auto* t = std::get_if<canonical::StraightTraverse>(&c.data)) out.push_back({t->end.x, t->end.y, t->end.z});
      if (auto* a = std::get_if<canonical::ArcFeed>(&c.data)) out.push_back({a->first_end, a->second_end, a->axis_end_point});
    }
    return out;
  }
  template <typename T>
  std::vector<T> all() const {
    std::vector<T> out;
    for (const auto& c : calls) {
      if (auto* x = std::get_if<T>(&c.data)) out.push_back(*x);
    }
    return out;
  }
};

struct Warnings {
  std::vector<std::pair<SourceLocation, std::string>> list;
};

Options options_for(Dialect dialect, Warnings* warnings = nullptr) {
  Options o;
  o.dialect = dialect;
  if (warnings) {
    o.warning = [warnings](const SourceLocation& where, const std::string& message) {
      warnings->list.emplace_back(where, message);
    };
  }
  return o;
}

ncbridge::setup::ToolList mill(int number, double diameter, double length) {
  ncbridge::setup::Tool t;
  t.number = number;
  t.type = ncbridge::setup::ToolType::FlatEndMill;
  t.diameter = diameter;
  t.length = length;
  return ncbridge::setup::ToolList({t});
}

Collect run(const std::string& text, const Options& options) {
  Collect sink;
  ncbridge::interpreter::interpret_text(text, "shop.prog", options, sink);
  return sink;
}

InputError error_of(const std::string& text, const Options& options) {
  try {
    run(text, options);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError({}, "");
}

bool near(const std::array<double, 3>& p, double x, double y, double z) {
  return std::fabs(p[0] - x) < 1e-6 && std::fabs(p[1] - y) < 1e-6 && std::fabs(p[2] - z) < 1e-6;
}

// ---- tool lengths

TEST(ToolLengths, G43WithoutAToolListUsesLengthZeroWithOneWarning) {
  const std::string program = "G21 G90\nT1 M6\nG43 H1\nG0 X10. Z5.\nT2 M6\nG43 H2\nG1 Z-1. F100\nM2\n";
  for (Dialect d : {Dialect::Rs274Ngc, Dialect::Fanuc, Dialect::Mach3}) {
    Warnings w;
    const Collect c = run(program, options_for(d, &w));
    const auto offsets = c.all<canonical::UseToolLengthOffset>();
    ASSERT_EQ(offsets.size(), 2u);
    EXPECT_EQ(offsets[0].offset.z, 0.0);
    // the tool-tip path: as programmed
    ASSERT_EQ(c.ends().size(), 2u);
    EXPECT_TRUE(near(c.ends()[0], 10, 0, 5));
    EXPECT_TRUE(near(c.ends()[1], 10, 0, -1));
    ASSERT_EQ(w.list.size(), 1u);
    EXPECT_EQ(w.list[0].first.line, 3u);
    EXPECT_EQ(w.list[0].first.column, 5u);
    EXPECT_NE(w.list[0].second.find("length 0"), std::string::npos) << w.list[0].second;
  }
}

TEST(ToolLengths, TheToolListsLengthWhenGivenAndStrictRefusesTheGuess) {
  Options o = options_for(Dialect::Rs274Ngc);
  o.tools = mill(1, 6, 42.5);
  const Collect c = run("G21\nT1 M6\nG43 H1\nG0 Z5\nM2\n", o);
  ASSERT_EQ(c.all<canonical::UseToolLengthOffset>().size(), 1u);
  EXPECT_EQ(c.all<canonical::UseToolLengthOffset>()[0].offset.z, 42.5);
  // a tool the list does not have stays an error
  EXPECT_EQ(error_of("G21\nT1 M6\nG43 H7\nM2\n", o).where().line, 3u);
  Options strict = options_for(Dialect::Fanuc);
  strict.strict = true;
  const InputError e = error_of("G21\nT1 M6\nG43 H1\nM30\n", strict);
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_NE(e.message().find("--strict"), std::string::npos) << e.message();
}

// ---- Mach3

TEST(Mach3, SemicolonCommentsRunToTheEndOfTheLine) {
  const Collect c = run("G21 G90 ; metric\nM06 T01  ; 0.0315\nG0 X1 Y2 ; (not a comment in parentheses)\nM30\n",
                        options_for(Dialect::Mach3));
  ASSERT_EQ(c.ends().size(), 1u);
  EXPECT_TRUE(near(c.ends()[0], 1, 2, 0));
  // Fanuc reads `;` as the end of the block: text after it is an error there
  EXPECT_EQ(error_of("G21 G90 ; metric\nM30\n", options_for(Dialect::Fanuc)).where().column, 11u);
}

// ---- Heidenhain

TEST(Heidenhain, BlocksOfMFunctionsAlone) {
  const Collect c = run("0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S1000\n2 M3\n3 M8\n4 L X+10 R0 FMAX\n5 M5 M9\n"
                        "6 END PGM T MM\n",
                        options_for(Dialect::Heidenhain));
  int on = 0, off = 0, flood = 0, dry = 0;
  for (const auto& call : c.calls) {
    on += std::holds_alternative<canonical::StartSpindleClockwise>(call.data) && call.source.line == 3;
    flood += std::holds_alternative<canonical::FloodOn>(call.data) && call.source.line == 4;
    off += std::holds_alternative<canonical::StopSpindleTurning>(call.data) && call.source.line == 6;
    dry += std::holds_alternative<canonical::FloodOff>(call.data) && call.source.line == 6;
  }
  EXPECT_EQ(on + flood + off + dry, 4);
}

TEST(Heidenhain, TildeContinuesABlockCommaIsADecimalSeparator) {
  const Collect c = run("0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S1000\n2 Q1 = 2,5 * ( 3 + ~\n   4 )\n"
                        "3 ; a comment that goes on ~\n  on the next line\n4 L X+Q1 Y+1,25 R0 F100\n"
                        "5 FN 12: IF +Q1 LT +18,85 GOTO LBL 1\n6 L X+0 R0 F100\n7 LBL 1\n8 END PGM T MM\n",
                        options_for(Dialect::Heidenhain));
  ASSERT_EQ(c.ends().size(), 1u);  // the jump to LBL 1 is taken: 17.5 < 18.85
  EXPECT_TRUE(near(c.ends()[0], 17.5, 1.25, 0));
  bool comment = false;
  for (const auto& call : c.calls) {
    if (auto* m = std::get_if<canonical::Comment>(&call.data)) comment |= m->text.find("goes on") != std::string::npos;
  }
  EXPECT_TRUE(comment);
}

TEST(Heidenhain, ContinuedCycleDefinitionAndItsErrorsNameTheirLine) {
  Options o = options_for(Dialect::Heidenhain);
  o.tools = mill(1, 6, 50);
  const Collect c = run("0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S1000\n2 L X+10 Y+10 Z+20 R0 FMAX M3\n"
                        "3 CYCL DEF 200 DRILLING ~\n  Q200=+2 ;SET-UP CLEARANCE ~\n  Q201=-10 ;DEPTH ~\n"
                        "  Q206=+150 ;FEED RATE FOR PLNGNG ~\n  Q202=+10 ;PLUNGING DEPTH ~\n"
                        "  Q210=+0 ;DWELL TIME AT TOP ~\n  Q203=+0 ;SURFACE COORDINATE ~\n"
                        "  Q204=+20 ;2ND SET-UP CLEARANCE ~\n  Q211=+0 ;DWELL TIME AT DEPTH\n"
                        "4 CYCL CALL\n5 END PGM T MM\n",
                        o);
  bool bottom = false;
  for (const auto& e : c.ends()) bottom |= near(e, 10, 10, -10);
  EXPECT_TRUE(bottom);
  // a bad parameter on the third line of a continued block: that line and its column
  const InputError e = error_of("0 BEGIN PGM T MM\n1 CYCL DEF 200 DRILLING ~\n  Q200=+2 ;SET-UP ~\n  Q201=-1 X5 ;DEPTH\n"
                                "2 END PGM T MM\n",
                                o);
  EXPECT_EQ(e.where().line, 4u);
  EXPECT_EQ(e.where().column, 11u);
}

TEST(Heidenhain, SysreadGivesToolDataAndPositionAndRefusesMachineData) {
  Options o = options_for(Dialect::Heidenhain);
  o.tools = mill(32, 10, 60);
  const Collect c = run("0 BEGIN PGM T MM\n1 FN 0: Q11 =+32\n2 TOOL CALL Q11 Z S1000\n3 FN 18: SYSREAD Q10 = ID50 NR2 IDXQ11\n"
                        "4 FN 18: SYSREAD Q12 = ID50 NR1\n5 L X+3 Y+4 Z+5 R0 FMAX\n6 FN 18: SYSREAD Q13 = ID270 NR1 IDX2\n"
                        "7 FN 18: SYSREAD Q14 = ID20 NR1\n8 L X+Q10 Y+Q13 Z+Q14 FQ12\n9 END PGM T MM\n",
                        o);
  ASSERT_EQ(c.ends().size(), 2u);
  EXPECT_TRUE(near(c.ends()[1], 5, 4, 32));
  bool feed = false;  // FQ12: the tool's length, 60
  for (const auto& f : c.all<canonical::SetFeedRate>()) feed |= f.rate == 60.0;
  EXPECT_TRUE(feed);
  const InputError e = error_of("0 BEGIN PGM T MM\n1 FN 18: SYSREAD Q1 = ID501 NR1 IDX2\n2 END PGM T MM\n", o);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 23u);
  EXPECT_NE(e.message().find("ID501 NR1"), std::string::npos) << e.message();
}

TEST(Heidenhain, ToleranceCycleSetsThePathTolerance) {
  const Collect c = run("0 BEGIN PGM T MM\n1 CYCL DEF 32.0 TOLERANCE\n2 CYCL DEF 32.1 T0,02\n3 CYCL DEF 32.2 HSC-MODE:0 TA0\n"
                        "4 END PGM T MM\n",
                        options_for(Dialect::Heidenhain));
  const auto modes = c.all<canonical::SetMotionControlMode>();
  ASSERT_FALSE(modes.empty());
  EXPECT_EQ(modes.back().mode, canonical::MotionControlMode::Continuous);
  EXPECT_NEAR(modes.back().tolerance, 0.02, 1e-12);
}

}  // namespace

namespace {

// ---- SINUMERIK 840D

TEST(Siemens840D, MessagesJoinTextAndValues) {
  const Collect c = run("R1=2.5\nDEF REAL D=4\nMSG(\"Depth \" << R1*2 << \" of \" << D << \" mm\")\nMSG(\"plain\")\nM30\n",
                        options_for(Dialect::Siemens840D));
  const auto messages = c.all<canonical::Message>();
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_EQ(messages[0].text, "Depth 5 of 4 mm");
  EXPECT_EQ(messages[1].text, "plain");
}

TEST(Siemens840D, GotoSearchesForwardThenBackward) {
  // GOTO finds the label after the block first; a label written twice is the nearest that way
  const Collect c = run("R1=0\nSTART:\nR1=R1+1\nIF R1==3 GOTO DONE\nG0 X=R1\nGOTO START\nDONE:\nG0 Y7\nM30\n",
                        options_for(Dialect::Siemens840D));
  ASSERT_EQ(c.ends().size(), 3u);
  EXPECT_TRUE(near(c.ends()[0], 1, 0, 0));
  EXPECT_TRUE(near(c.ends()[1], 2, 0, 0));
  EXPECT_TRUE(near(c.ends()[2], 2, 7, 0));
}

TEST(Siemens840D, ShopMillHeaderAndEndAreReadItsStepsRefusedByName) {
  const Collect c = run("N10 G17 G90 DIAMOF;*GP*;*RO*;*HD*\nN15 E_HEAD(1,\"PART\",0.5,100,0,2,0,1,0)\n"
                        "N20 G0 X10 Y10 Z50\nN25 E_END(1,0,0)\n",
                        options_for(Dialect::Siemens840D));
  ASSERT_EQ(c.ends().size(), 1u);
  EXPECT_FALSE(c.all<canonical::ProgramEnd>().empty());
  const InputError e = error_of("N10 G17 G90\nN15 E_HEAD(1,\"PART\",0.5,100,0,2,0,1,0)\nN20 E_MI_PL(1,2,3)\nN25 E_END(1,0,0)\n",
                                options_for(Dialect::Siemens840D));
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().column, 5u);
  EXPECT_NE(e.message().find("E_MI_PL (face milling)"), std::string::npos) << e.message();
}

TEST(Siemens840D, HighSpeedSettingsCycleSetsThePathTolerance) {
  const Collect c = run("CYCLE832(0.05,0,1)\nM30\n", options_for(Dialect::Siemens840D));
  const auto modes = c.all<canonical::SetMotionControlMode>();
  ASSERT_FALSE(modes.empty());
  EXPECT_NEAR(modes.back().tolerance, 0.05, 1e-12);
}

TEST(Siemens840D, UnknownCallsAndTiltedFramesAreLocated) {
  InputError e = error_of("N10 G0 X0\nN20 NOSUCH(1,2)\nM30\n", options_for(Dialect::Siemens840D));
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 5u);
  EXPECT_NE(e.message().find("NOSUCH.SPF"), std::string::npos) << e.message();
  e = error_of("N10 G0 X0\nN20 ROT Y-90\nM30\n", options_for(Dialect::Siemens840D));
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().column, 5u);
  EXPECT_NE(e.message().find("angle head"), std::string::npos) << e.message();
}

}  // namespace
