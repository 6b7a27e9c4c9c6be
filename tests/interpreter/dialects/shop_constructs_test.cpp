// Constructs of real shop programs (issue 20) through the library API, each with its canonical
// result worked out by hand: G43 without tool lengths, Mach3 `;` comments, Heidenhain blocks of
// M functions, `~` continuation, comma decimals, FN 18, cycle 32; errors and warnings located.
#include <gtest/gtest.h>

#include <map>

#include <algorithm>
#include <array>
#include <set>
#include <optional>
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

namespace {

// ---- Fanuc custom macro B and machine functions

TEST(FanucMacroB, VacantVariablesFollowTheNullRules) {
  // #1 is vacant: copying keeps it vacant, arithmetic gives 0, EQ/NE tell it from 0, LT reads 0,
  // an address with it is left out
  const Collect c = run("G21 G90\nG0 X1. Y1. Z1.\n#2=#1\n#3=#1+#1\n"
                        "IF [#2 EQ #0] THEN #10=1.\nIF [#3 EQ #0] THEN #11=1.\nIF [#1 EQ 0] THEN #12=1.\n"
                        "IF [#1 LT 1.] THEN #13=1.\nIF [#3 EQ 0] THEN #14=1.\n"
                        "G0 X[#10+#11*10.+#12*100.] Y[#13+#14*10.] Z#2\nM30\n",
                        options_for(Dialect::Fanuc));
  ASSERT_EQ(c.ends().size(), 2u);
  EXPECT_TRUE(near(c.ends()[1], 1, 11, 1));
  // #0 cannot be assigned
  EXPECT_EQ(error_of("G21\n#0=1.\nM30\n", options_for(Dialect::Fanuc)).where().line, 2u);
}

TEST(FanucMacroB, G65ArgumentListTwoTakesRepeatedIJK) {
  const Collect c = run("G21 G90\nG65 P9001 A2. I1. J2. I3. K4. I5.\nM30\nO9001\nG0 X#4 Y#5 Z#6\nG0 X#7 Y#8 Z#9\n"
                        "G0 X#10 Y[#1] Z[#11+#2]\nM99\n",
                        options_for(Dialect::Fanuc));
  ASSERT_EQ(c.ends().size(), 3u);
  EXPECT_TRUE(near(c.ends()[0], 1, 2, 0));   // I1 J1; K1 vacant: Z left out
  EXPECT_TRUE(near(c.ends()[1], 3, 2, 4));   // I2 (J2 vacant) K2
  EXPECT_TRUE(near(c.ends()[2], 5, 2, 0));   // I3; #2 (B) vacant reads 0
}

TEST(FanucMacroB, WorkOffsetSettingAndTheExternalOffset) {
  const Collect c = run("G21 G90\nG10 L2 P2 X10. Y20.\nG91 G10 L2 P2 X5.\nG90 G55 G0 X0 Y0\nM30\n",
                        options_for(Dialect::Fanuc));
  std::optional<canonical::SetG5xOffset> g55;  // the last of G55's (M30 then selects G54)
  for (const auto& o : c.all<canonical::SetG5xOffset>()) {
    if (o.index == 2) g55 = o;
  }
  ASSERT_TRUE(g55.has_value());
  EXPECT_NEAR(g55->offset.x, 15.0, 1e-9);  // G91: 10 + 5
  EXPECT_NEAR(g55->offset.y, 20.0, 1e-9);
}

// G10 L2 P0 sets the external work offset (EXOFS), which Fanuc adds to every work offset:
// G54-G59 set before or after it, and the additional ones (G54.1); in G91 it is added to.
TEST(FanucMacroB, ExternalWorkOffsetShiftsEveryWorkOffset) {
  const Collect c = run("G21 G90\nG10 L2 P1 X10. Y20.\nG10 L2 P0 X5. Y-2.\nG10 L2 P2 X100.\nG91 G10 L2 P0 X1. Z-3.\n"
                        "G90 G10 L20 P3 X200.\nG54 G0 X0 Y0\nG55 X0 Y0\nG54.1 P3 X0 Y0\nM30\n",
                        options_for(Dialect::Fanuc));
  std::map<int, std::vector<canonical::SetG5xOffset>> by_system;
  for (const auto& o : c.all<canonical::SetG5xOffset>()) by_system[o.index].push_back(o);
  ASSERT_FALSE(by_system[1].empty());
  ASSERT_FALSE(by_system[2].empty());
  ASSERT_FALSE(by_system[9].empty());
  // the offsets in force when each is selected (before M30)
  auto selected = [&](int system) {
    for (auto it = by_system[system].rbegin(); it != by_system[system].rend(); ++it) {
      if (it->offset.x != 0 || it->offset.y != 0 || it->offset.z != 0) return *it;
    }
    return by_system[system].back();
  };
  EXPECT_NEAR(selected(1).offset.x, 16.0, 1e-9);  // 10 + EXOFS 5 + 1
  EXPECT_NEAR(selected(1).offset.y, 18.0, 1e-9);  // 20 - 2
  EXPECT_NEAR(selected(1).offset.z, -3.0, 1e-9);
  EXPECT_NEAR(selected(2).offset.x, 106.0, 1e-9);  // set after EXOFS: 100 + 5, then + 1
  EXPECT_NEAR(selected(2).offset.y, -2.0, 1e-9);
  EXPECT_NEAR(selected(9).offset.x, 206.0, 1e-9);  // G54.1 P3: 200 + 6
  EXPECT_NEAR(selected(9).offset.z, -3.0, 1e-9);
  const InputError e = error_of("G21\nG10 L2 P0 B5.\nM30\n", options_for(Dialect::Fanuc));
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_NE(e.message().find("external work offset of a rotary axis"), std::string::npos) << e.message();
}

TEST(FanucMacroB, MachineFunctionsWarnAndStrictRefuses) {
  Warnings w;
  Options o = options_for(Dialect::Fanuc, &w);
  o.machine_functions = {444};
  const Collect c = run("G21\nM10\nG0 X1.\nM444\nM30\n", o);
  ASSERT_EQ(w.list.size(), 2u);
  EXPECT_EQ(w.list[0].first.line, 2u);
  EXPECT_NE(w.list[0].second.find("M10 (rotary axis clamp)"), std::string::npos) << w.list[0].second;
  EXPECT_EQ(w.list[1].first.line, 4u);
  o.strict = true;
  EXPECT_EQ(error_of("G21\nM10\nM30\n", o).where().line, 2u);
  // an M code no list names stays an error
  EXPECT_EQ(error_of("G21\nM445\nM30\n", options_for(Dialect::Fanuc)).where().line, 2u);
}

}  // namespace

namespace {

// ---- Heidenhain SL cycles and the pocket cycles built on them: properties of the motion

struct Cut {
  double x, y, z;
};

// The feed moves below the surface, as points (arcs' end points: the SL cycles cut lines).
std::vector<std::pair<Cut, Cut>> cuts_below(const Collect& c, double surface) {
  std::vector<std::pair<Cut, Cut>> out;
  Cut here{0, 0, 1e9};
  for (const auto& call : c.calls) {
    Cut to = here;
    bool feed = false;
    if (auto* f = std::get_if<canonical::StraightFeed>(&call.data)) {
      to = {f->end.x, f->end.y, f->end.z};
      feed = true;
    } else if (auto* t = std::get_if<canonical::StraightTraverse>(&call.data)) {
      to = {t->end.x, t->end.y, t->end.z};
    } else if (auto* a = std::get_if<canonical::ArcFeed>(&call.data)) {
      to = {a->first_end, a->second_end, a->axis_end_point};
    }
    if (feed && to.z < surface - 1e-9 && std::fabs(to.z - here.z) < 1e-9) out.emplace_back(here, to);
    here = to;
  }
  return out;
}

double distance_to_segment(double px, double py, const Cut& a, const Cut& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((px - a.x) * dx + (py - a.y) * dy) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(px - (a.x + t * dx), py - (a.y + t * dy));
}

// A pocket 80 x 60 with a square island 10-25 x 10-25 and a round island R10 about (60, 40),
// the contours in their own labels with RR/RL as SL-II wants; tool 1 is 10 mm.
const char* kSlProgram =
    "0 BEGIN PGM SL MM\n1 TOOL CALL 1 Z S3000\n2 L Z+50 R0 FMAX M3\n"
    "3 CYCL DEF 14.0 CONTOUR\n4 CYCL DEF 14.1 CONTOUR LABEL 1 /2 /3\n"
    "5 CYCL DEF 20 CONTOUR DATA ~\n  Q1=-6 ;MILLING DEPTH ~\n  Q2=+1.2 ;TOOL PATH OVERLAP ~\n"
    "  Q3=+0.5 ;ALLOWANCE FOR SIDE ~\n  Q4=+0.3 ;ALLOWANCE FOR FLOOR ~\n  Q5=+0 ;SURFACE COORDINATE ~\n"
    "  Q6=+2 ;SET-UP CLEARANCE ~\n  Q7=+30 ;CLEARANCE HEIGHT ~\n  Q8=+0 ;ROUNDING RADIUS ~\n  Q9=+1 ;ROTATIONAL DIRECTION\n"
    "6 CYCL DEF 22 ROUGH-OUT ~\n  Q10=-2.5 ;PLUNGING DEPTH ~\n  Q11=+100 ;FEED RATE FOR PLNGNG ~\n"
    "  Q12=+600 ;FEED RATE F. ROUGHNG ~\n  Q18=+0 ;COARSE ROUGHING TOOL ~\n  Q19=+0 ;FEED RATE FOR RECIP.\n"
    "7 CYCL CALL\n8 L Z+50 R0 FMAX M30\n"
    "9 LBL 1\n10 L X+0 Y+30 RR\n11 L Y+60\n12 L X+80\n13 L Y+0\n14 L X+0\n15 L Y+30\n16 LBL 0\n"
    "17 LBL 2\n18 L X+10 Y+15 RL\n19 L Y+25\n20 L X+25\n21 L Y+10\n22 L X+10\n23 L Y+15\n24 LBL 0\n"
    "25 LBL 3\n26 CC X+60 Y+40\n27 L X+60 Y+50 RR\n28 C X+60 Y+50 DR+\n29 LBL 0\n30 END PGM SL MM\n";

TEST(HeidenhainSl, RoughOutClearsThePocketAroundItsIslandsLayerByLayer) {
  Options o = options_for(Dialect::Heidenhain);
  o.tools = mill(1, 10, 50);
  const Collect c = run(kSlProgram, o);
  const auto cuts = cuts_below(c, 0.0);
  ASSERT_GT(cuts.size(), 50u);
  // layers of Q10 down to the depth less the floor allowance: -2.5, -5, -5.7
  std::set<double> levels;
  for (const auto& [a, b] : cuts) levels.insert(std::round(b.z * 1000) / 1000);
  EXPECT_EQ(levels, (std::set<double>{-5.7, -5.0, -2.5}));
  // the tool centre keeps the tool radius plus the side allowance from every wall and island
  double wall = 1e9, square = 1e9, round = 1e9;
  for (const auto& [a, b] : cuts) {
    for (const Cut& p : {a, b}) {
      wall = std::min({wall, p.x, 80 - p.x, p.y, 60 - p.y});
      square = std::min(square, std::hypot(std::max({10 - p.x, 0.0, p.x - 25}), std::max({10 - p.y, 0.0, p.y - 25})));
      round = std::min(round, std::hypot(p.x - 60, p.y - 40) - 10);
    }
  }
  EXPECT_NEAR(wall, 5.5, 1e-3);
  EXPECT_NEAR(square, 5.5, 1e-2);
  EXPECT_NEAR(round, 5.5, 1e-2);
  // and leaves nothing the tool can reach uncut: every point of the deepest layer's area (the
  // tool centre's region) lies within the tool radius of a cut
  int points = 0;
  for (double x = 5.5; x <= 74.5; x += 1.5) {
    for (double y = 5.5; y <= 54.5; y += 1.5) {
      const double to_square = std::hypot(std::max({10 - x, 0.0, x - 25}), std::max({10 - y, 0.0, y - 25}));
      if (to_square < 5.5 || std::hypot(x - 60, y - 40) - 10 < 5.5) continue;
      double nearest = 1e9;
      for (const auto& [a, b] : cuts) {
        if (std::fabs(b.z + 5.7) < 1e-6) nearest = std::min(nearest, distance_to_segment(x, y, a, b));
      }
      EXPECT_LE(nearest, 5.0 + 1e-6) << "(" << x << ", " << y << ") is left";
      ++points;
    }
  }
  EXPECT_GT(points, 800);
  // finally up to the clearance height Q7
  EXPECT_NEAR(c.ends().back()[2], 50.0, 1e-9);  // the program's own last move
}

TEST(HeidenhainSl, ContourWithoutCompensationAndUnknownBlocksAreLocated) {
  Options o = options_for(Dialect::Heidenhain);
  o.tools = mill(1, 10, 50);
  std::string program = kSlProgram;
  program.replace(program.find("10 L X+0 Y+30 RR"), 16, "10 L X+0 Y+30 R0");
  InputError e = error_of(program, o);
  EXPECT_EQ(e.where().line, 22u);  // the CYCL CALL
  EXPECT_NE(e.message().find("LBL 1 has no radius compensation"), std::string::npos) << e.message();
  program = kSlProgram;
  program.replace(program.find("13 L Y+0"), 8, "13 CT X+80 Y+0");
  e = error_of(program, o);
  EXPECT_NE(e.message().find("CT in an SL contour"), std::string::npos) << e.message();
}

TEST(HeidenhainPockets, CircularPocketOnACartesianPattern) {
  Options o = options_for(Dialect::Heidenhain);
  o.tools = mill(1, 10, 50);
  const Collect c = run(
      "0 BEGIN PGM P MM\n1 TOOL CALL 1 Z S3000\n2 L Z+50 R0 FMAX M3\n"
      "3 CYCL DEF 252 CIRCULAR POCKET ~\n  Q215=+0 ;MACHINING OPERATION ~\n  Q223=+30 ;CIRCLE DIAMETER ~\n"
      "  Q368=+0.2 ;ALLOWANCE FOR SIDE ~\n  Q207=+500 ;FEED RATE FOR MILLNG ~\n  Q351=+1 ;CLIMB OR UP-CUT ~\n"
      "  Q201=-4 ;DEPTH ~\n  Q202=+2 ;PLUNGING DEPTH ~\n  Q369=+0.1 ;ALLOWANCE FOR FLOOR ~\n"
      "  Q206=+150 ;FEED RATE FOR PLNGNG ~\n  Q338=+0 ;INFEED FOR FINISHING ~\n  Q200=+2 ;SET-UP CLEARANCE ~\n"
      "  Q203=+0 ;SURFACE COORDINATE ~\n  Q204=+20 ;2ND SET-UP CLEARANCE ~\n  Q370=+1 ;TOOL PATH OVERLAP ~\n"
      "  Q366=+0 ;PLUNGE ~\n  Q385=+300 ;FINISHING FEED RATE\n"
      "4 CYCL DEF 221 CARTESIAN PATTERN ~\n  Q225=+20 ;STARTNG PNT 1ST AXIS ~\n  Q226=+30 ;STARTNG PNT 2ND AXIS ~\n"
      "  Q237=+50 ;SPACING IN 1ST AXIS ~\n  Q238=+40 ;SPACING IN 2ND AXIS ~\n  Q242=+2 ;NUMBER OF COLUMNS ~\n"
      "  Q243=+2 ;NUMBER OF LINES ~\n  Q224=+0 ;ANGLE OF ROTATION ~\n  Q200=+2 ;SET-UP CLEARANCE ~\n"
      "  Q203=+0 ;SURFACE COORDINATE ~\n  Q204=+20 ;2ND SET-UP CLEARANCE ~\n  Q301=+1 ;MOVE TO CLEARANCE\n"
      "5 L Z+50 R0 FMAX M30\n6 END PGM P MM\n",
      o);
  const auto cuts = cuts_below(c, 0.0);
  ASSERT_FALSE(cuts.empty());
  // four pockets: the tool centre reaches the wall less the radius (finished: 15 - 5 = 10) and
  // the floor at -4; roughing stays 0.2 inside and 0.1 above
  for (const auto& [cx, cy] : std::vector<std::pair<double, double>>{{20, 30}, {70, 30}, {20, 70}, {70, 70}}) {
    double reach = 0, deepest = 0;
    for (const auto& [a, b] : cuts) {
      const double d = std::hypot(b.x - cx, b.y - cy);
      if (d < 12) {
        reach = std::max(reach, d);
        deepest = std::min(deepest, b.z);
      }
    }
    EXPECT_NEAR(reach, 10.0, 0.01) << cx << ", " << cy;
    EXPECT_NEAR(deepest, -4.0, 1e-9) << cx << ", " << cy;
  }
}

}  // namespace

namespace {

TEST(HeidenhainPockets, OldPocketMillingCycleFour) {
  Options o = options_for(Dialect::Heidenhain);
  o.tools = mill(1, 10, 50);
  const Collect c = run("0 BEGIN PGM P4 MM\n1 TOOL CALL 1 Z S3000\n2 L Z+50 R0 FMAX M3\n"
                        "3 CYCL DEF 4.0 POCKET MILLING\n4 CYCL DEF 4.1 SET UP -2\n5 CYCL DEF 4.2 DEPTH -7\n"
                        "6 CYCL DEF 4.3 PECKG -4 F80\n7 CYCL DEF 4.4 X+60\n8 CYCL DEF 4.5 Y+40\n"
                        "9 CYCL DEF 4.6 F300 DR+ RADIUS 8\n10 L X+50 Y+30 R0 FMAX\n11 L Z+2 R0 FMAX\n"
                        "12 CYCL CALL\n13 L Z+50 R0 FMAX M30\n14 END PGM P4 MM\n",
                        o);
  const auto cuts = cuts_below(c, 0.0);
  ASSERT_FALSE(cuts.empty());
  std::set<double> levels;
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  for (const auto& [a, b] : cuts) {
    levels.insert(std::round(b.z * 1000) / 1000);
    xmin = std::min(xmin, b.x); xmax = std::max(xmax, b.x); ymin = std::min(ymin, b.y); ymax = std::max(ymax, b.y);
  }
  EXPECT_EQ(levels, (std::set<double>{-7.0, -4.0}));  // the plunging depth from the surface Z0
  EXPECT_NEAR(xmin, 25.0, 1e-3);  // the centre X50, 60 long, less the tool radius
  EXPECT_NEAR(xmax, 75.0, 1e-3);
  EXPECT_NEAR(ymin, 15.0, 1e-3);
  EXPECT_NEAR(ymax, 45.0, 1e-3);
  // back at the starting position before the program's next block
  const auto ends = c.ends();
  ASSERT_GE(ends.size(), 2u);
  EXPECT_TRUE(near(ends[ends.size() - 2], 50, 30, 2));
}

}  // namespace
