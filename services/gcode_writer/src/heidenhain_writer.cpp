// HEIDENHAIN TNC conversational (Klartext), as services/interpreter/src/heidenhain/ reads it:
// numbered blocks between BEGIN PGM and END PGM, L X+.. Y+.. Z+.. R0 FMAX|F.., CC + C/CP for
// arcs in the XY plane (CP IPA.. IZ.. for a helix of several turns), TOOL CALL n Z S.. (the tool
// change, its length compensation, a length oversize DL to reach another offset; TOOL CALL Z S..
// alone changes the speed), TOOL DEF n, M functions on the path blocks (M3/M4/M8 act before the
// motion, M5/M9/M1/M2 after it), STOP, the drilling cycles 200/201/203/207 with CYCL CALL or M99,
// CYCL DEF 9 for a dwell, LBL n ... CALL LBL n REP for the repeat construct. What the TNC program cannot say here is
// refused: unit changes, work offsets, G92, XY rotation, a length offset change without a tool
// change, feed per revolution, G96, path control modes, overrides, mist
// coolant, arcs outside XY, rotary axes, M19, M60, M61, tool table writes, G33.
#include <cmath>
#include <numbers>
#include <optional>

#include "cycle_motion.hpp"
#include "dialect_writer.hpp"
#include "motion_trace.hpp"
#include "number_format.hpp"
#include "word_address_writer.hpp"

namespace ncbridge::gcode_writer {

using namespace canonical;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// The names the control shows beside a cycle's Q parameters.
std::string_view q_parameter_name(std::string_view q) {
  static constexpr std::pair<std::string_view, std::string_view> kNames[] = {
      {"Q200", "SET-UP CLEARANCE"}, {"Q201", "DEPTH"}, {"Q202", "PLUNGING DEPTH"}, {"Q203", "SURFACE COORDINATE"},
      {"Q204", "2ND SET-UP CLEARANCE"}, {"Q205", "MIN. PLUNGING DEPTH"}, {"Q206", "FEED RATE FOR PLUNGING"},
      {"Q208", "RETRACTION FEED RATE"}, {"Q210", "DWELL TIME AT TOP"}, {"Q211", "DWELL TIME AT DEPTH"},
      {"Q212", "DECREMENT"}, {"Q213", "NR OF BREAKS"}, {"Q239", "PITCH"}, {"Q256", "DIST. FOR CHIP BRKNG"}};
  for (const auto& [name, text] : kNames) {
    if (name == q) return text;
  }
  return {};
}

class HeidenhainWriter final : public DialectWriter {
 public:
  using DialectWriter::DialectWriter;

  void begin_program(const MachineState& desired) override {
    inch_ = desired.units == Units::Inches;
    reader_.apply(UseLengthUnits{desired.units});
    block(concat({"BEGIN PGM ", name(), inch_ ? " INCH" : " MM"}));
  }

  void sync(const MachineState& d, unsigned need) override;
  void traverse(const Pose& end) override { path_move(end, true); }
  void feed(const Pose& end) override { path_move(end, false); }
  void arc(const ArcFeed& a) override;
  void dwell(double seconds) override {
    flush_tool_call();
    flush_before();
    flush_path();
    block("CYCL DEF 9.0 DWELL TIME");
    std::string s = "CYCL DEF 9.1 DWELL ";
    append_number(s, rounded(seconds, 4), NumberStyle{4, false, false});
    block(s);
    reader_.apply(Dwell{rounded(seconds, 4)});
  }
  void tool_change(int tool) override {
    flush_before();
    flush_tool_call();
    pending_tool_ = tool;
  }
  void action(const Call& call, const MachineState& desired) override;
  bool cycle(const Hole& hole, const MachineState& desired) override;
  void comment(std::string_view text) override {
    if (pending_tool_) {  // after the TOOL CALL, which waits for the next action
      held_comments_.push_back(clean(text));
      return;
    }
    flush_path();
    block(concat({"; ", clean(text)}));
  }
  void message(std::string_view text) override { comment(text); }
  void program_end(bool rewind) override {
    flush_tool_call();
    flush_before();
    if (!rewind) after_m("M2");  // END PGM ends with M30 (and the pallet shuttle that comes with it)
    flush_path();
    block(concat({"END PGM ", name(), inch_ ? " INCH" : " MM"}));
    ended_ = true;
  }
  void end_program(bool ended) override {
    if (!ended) cannot("a program that ends at its end of tape (no M2/M30)", "a TNC program ends with END PGM");
    flush_path();
  }
  void begin_repeat(std::uint32_t count, double z_shift) override;
  void end_repeat() override;

 private:
  std::string name() const {
    std::string n;
    for (char c : options_.program_name) n.push_back(c == ' ' ? '_' : c);
    return n.empty() ? "NCBRIDGE" : n;
  }
  static std::string clean(std::string_view text) {
    std::string s;
    for (char c : text) s.push_back(c == '\n' || c == '\r' ? ' ' : c);
    return s;
  }
  [[noreturn]] void cannot(const std::string& construct, const std::string& why = {}) const { refuse(construct, why); }

  // numbered blocks
  void block(std::string_view text) {
    out_.line() += number_text(static_cast<long long>(number_++));
    out_.line().push_back(' ');
    out_.line() += text;
    out_.end_line();
  }
  void raw_line(std::string_view text) {
    out_.line() += text;
    out_.end_line();
  }
  double length(double v) const { return rounded(v, length_decimals()); }
  void coordinate(std::string& s, const char* letter, double v, int decimals) const {
    s.push_back(' ');
    s += letter;
    append_number(s, v, NumberStyle{decimals, false, true});
  }
  void append_feed(std::string& s, double f) const {
    s += " F";
    append_number(s, f, NumberStyle{length_decimals(), false, false});
  }

  // The last path block, held back so that M functions acting after its motion join it.
  void flush_path() {
    if (!path_) return;
    std::string text = *path_;
    path_.reset();
    block(text);
  }
  void after_m(std::string_view m) {
    if (!path_) {
      flush_before();
      path_ = still_block();
    }
    *path_ += ' ';
    *path_ += m;
  }
  // A block that does not move (a rapid to where the tool is): where a TNC program puts M
  // functions that go with no motion.
  std::string still_block() {
    std::string s(1, 'L');
    coordinate(s, incremental_ ? "IZ" : "Z", incremental_ ? 0.0 : reader_.position.z, length_decimals());
    s += " R0 FMAX";
    reader_.apply(StraightTraverse{reader_.position});
    return s;
  }
  // M functions acting before the motion of the next path block (M3, M4, M8).
  void flush_before() {
    if (before_.empty()) return;
    flush_path();
    std::string s = still_block();
    s += before_;
    before_.clear();
    block(s);
  }

  void flush_tool_call();
  void path_move(const Pose& end, bool rapid);
  void start_path_block(std::string& s, const char* keyword);

  bool inch_ = false;
  bool ended_ = false;
  std::uint64_t number_ = 0;
  std::optional<std::string> path_;
  std::string before_;                 // " M3 M8": for the next path block
  std::optional<int> pending_tool_;    // a TOOL CALL to write once its length offset is known
  double programmed_feed_ = std::nan("");  // the reader's last F (mm or inch per minute)
  bool incremental_ = false;
  Pose repeat_start_{};
  std::uint32_t repeat_count_ = 0;
  double repeat_shift_ = 0;
  int label_ = 0;
  // the cycle defined last (CYCL DEF and its Q parameters), to call it again
  std::string cycle_definition_;
  double wanted_feed_ = 0;  // the feed the next feed move needs (set by sync)
  bool said_dropped_ = false;
  std::vector<std::string> held_comments_;  // comments that came after a tool change not yet written
};

void HeidenhainWriter::sync(const MachineState& d, unsigned need) {
  if ((need & (kFrame | kUnits)) != 0 && reader_.units != d.units) {
    cannot("a change of units within the program", "BEGIN PGM fixes MM or INCH");
  }
  if ((need & kFrame) != 0) {
    if (d.coord_system != 1 || !near(d.g5x_mm[1], Pose{}, 1e-9) || !near(d.origin_mm(), Pose{}, 1e-9)) {
      cannot("a work offset (G54-G59.3 values, G10 L2, G92)", "the TNC's datums are its preset table, not program words read back here");
    }
    if (!near(d.active_rotation(), 0, 1e-9)) cannot("SET_XY_ROTATION (a rotated coordinate system)");
  }
  if ((need & (kActuators | kFrame)) != 0 && pending_tool_) {
    // the tool change, written with what the next action needs: its speed and length offset
    const int tool = *pending_tool_;
    pending_tool_.reset();
    const setup::Tool* t = options_.tools.find(tool);
    setup::Tool no_tool;  // T0: the spindle empty, no length
    if (tool == 0) t = &no_tool;
    if (t == nullptr) {
      cannot(concat({"TOOL CALL ", number_text(tool), " of a tool that is not in the tool list"}),
             "give the tool list the program runs with");
    }
    flush_path();
    std::string s = concat({"TOOL CALL ", number_text(tool), " Z"});
    const double k = reader_.mm_per_unit();
    if (d.speed != reader_.speed) {
      s += " S";
      append_number(s, rounded(d.speed, 4), NumberStyle{4, false, false});
      reader_.apply(SetSpindleSpeed{0, rounded(d.speed, 4)});
    }
    Pose length;
    length.x = t->x_offset;
    length.z = t->length;
    if (reader_.plane != Plane::XY) reader_.apply(SelectPlane{Plane::XY});
    reader_.apply(SelectTool{tool});
    reader_.apply(StartChange{});
    reader_.apply(StopSpindleTurning{0});
    reader_.apply(ChangeTool{0});
    if (near(d.tool_offset_mm, length, 1e-9)) {
      reader_.apply(UseToolLengthOffset{from_mm(length, k)});
    } else {
      Pose other = d.tool_offset_mm;
      other.z = 0;
      if (!near(other, Pose{}, 1e-9)) cannot("a tool length offset with other than a Z component (G43.1 X..)");
      const double dl = length_decimals() > 0 ? rounded(d.tool_offset_mm.z / k - t->length / k, length_decimals()) : 0;
      coordinate(s, "DL", dl, length_decimals());
      Pose dynamic;
      dynamic.z = t->length / k + dl;
      reader_.apply(UseToolLengthOffset{dynamic});
    }
    block(s);
    for (const std::string& c : held_comments_) block(concat({"; ", c}));
    held_comments_.clear();
  }
  if ((need & kToolSelect) != 0 && d.selected_tool >= 0 && d.selected_tool != reader_.selected_tool) {
    flush_before();
    flush_path();
    block(concat({"TOOL DEF ", number_text(d.selected_tool)}));
    reader_.apply(SelectTool{d.selected_tool});
  }
  if ((need & kFrame) != 0 && !near(reader_.tool_offset_mm, d.tool_offset_mm, 1e-9)) {
    cannot("a change of the tool length offset without a tool change (G43/G49)", "TOOL CALL sets it with the tool");
  }
  if ((need & kPlane) != 0 && d.plane != Plane::XY) {
    cannot(d.plane == Plane::XZ ? "an arc or cycle in the XZ plane (G18)" : d.plane == Plane::YZ ? "an arc or cycle in the YZ plane (G19)"
                                                                         : "an arc or cycle outside the XY plane",
           "it reads CC/C and the cycles in the XY plane only");
  }
  if ((need & kFeed) != 0) {
    if (d.feed_mode != 0) cannot("feed per revolution (G95)");
    if (d.feed_reference != FeedReference::Xyz) cannot("SET_FEED_REFERENCE(CANON_WORKPIECE)");
    if (d.feed_override != reader_.feed_override || d.speed_override != reader_.speed_override ||
        d.adaptive_feed != reader_.adaptive_feed || d.feed_hold != reader_.feed_hold) {
      cannot("switching feed or speed overrides (M48-M53)");
    }
  }
  if ((need & kPath) != 0 && (d.control != reader_.control || d.tolerance != reader_.tolerance ||
                              d.naive_tolerance != reader_.naive_tolerance)) {
    const bool only_tolerance = d.control == MotionControlMode::Continuous && reader_.control == d.control;
    if (!only_tolerance) cannot("a path control mode (G61, G61.1)");
    if (!options_.drop_path_tolerance) {
      cannot("a path blending tolerance (G64 P)", "the TNC's contouring has none (--drop-path-tolerance writes it without)");
    }
    if (!said_dropped_) {
      comment("ncbridge: G64 P (LinuxCNC's path tolerance) not written: the control blends by its own settings");
      said_dropped_ = true;
    }
  }
  if ((need & kActuators) != 0) {
    if (!near(reader_.css_maximum, d.css_maximum, 1e-9)) cannot("constant surface speed (G96/G97)");
    const double speed = rounded(d.speed, 4);
    if (speed != reader_.speed) {
      flush_before();
      flush_path();
      std::string s = "TOOL CALL Z S";
      append_number(s, speed, NumberStyle{4, false, false});
      block(s);
      if (reader_.plane != Plane::XY) reader_.apply(SelectPlane{Plane::XY});
      reader_.apply(SetSpindleSpeed{0, speed});
    }
    if (d.mist && !reader_.mist) cannot("mist coolant (M7)");
    if (d.spindle != reader_.spindle) {
      if (d.spindle == Direction::Stopped) {
        after_m("M5");
        reader_.apply(StopSpindleTurning{0});
      } else {
        before_ += d.spindle == Direction::Clockwise ? " M3" : " M4";
        if (d.spindle == Direction::Clockwise) reader_.apply(StartSpindleClockwise{0});
        else reader_.apply(StartSpindleCounterclockwise{0});
      }
    }
    if ((reader_.flood && !d.flood) || (reader_.mist && !d.mist)) {
      after_m("M9");
      reader_.apply(MistOff{});
      reader_.apply(FloodOff{});
    }
    if (d.flood && !reader_.flood) {
      before_ += " M8";
      reader_.apply(FloodOn{});
    }
  }
  if ((need & kFeed) != 0) {
    const double k = reader_.mm_per_unit();
    const double f = length(d.feed_mm / k);
    wanted_feed_ = f;
  }
}

void HeidenhainWriter::flush_tool_call() {
  if (!pending_tool_) return;
  // no action came that needs a speed or a length offset: the tool with its own length
  MachineState d = reader_;
  d.tool_offset_mm = Pose{};
  if (const setup::Tool* t = options_.tools.find(*pending_tool_); t != nullptr && *pending_tool_ != 0) {
    d.tool_offset_mm.x = t->x_offset;
    d.tool_offset_mm.z = t->length;
  }
  sync(d, kFrame);
}

void HeidenhainWriter::start_path_block(std::string& s, const char* keyword) {
  flush_path();
  s.clear();
  s.append(keyword);
}

void HeidenhainWriter::path_move(const Pose& end, bool rapid) {
  flush_tool_call();
  const Pose here = reader_.position;
  Pose e = end;
  for (double Pose::*f : {&Pose::a, &Pose::b, &Pose::c, &Pose::u, &Pose::v, &Pose::w}) {
    if (!near(end.*f, here.*f, 1e-9)) cannot("a move of a rotary or U/V/W axis");
    e.*f = here.*f;
  }
  e.x = length(end.x);
  e.y = length(end.y);
  e.z = length(end.z);
  std::string s;
  start_path_block(s, "L");
  bool any = false;
  const char* letters[3] = {"X", "Y", "Z"};
  const char* inc_letters[3] = {"IX", "IY", "IZ"};
  double Pose::*fields[3] = {&Pose::x, &Pose::y, &Pose::z};
  for (int i = 0; i < 3; ++i) {
    const double v = e.*fields[i], now = here.*fields[i];
    if (v == now) continue;
    coordinate(s, incremental_ ? inc_letters[i] : letters[i], incremental_ ? length(v - now) : v, length_decimals());
    any = true;
  }
  if (!any) coordinate(s, incremental_ ? "IZ" : "Z", incremental_ ? 0.0 : here.z, length_decimals());
  s += " R0";
  if (rapid) {
    s += " FMAX";
  } else {
    if (!(wanted_feed_ > 0)) cannot("a feed move with no feed rate");
    if (!(programmed_feed_ == wanted_feed_)) {
      append_feed(s, wanted_feed_);
      programmed_feed_ = wanted_feed_;
    }
    reader_.apply(SetFeedRate{programmed_feed_});
  }
  s += before_;
  before_.clear();
  path_ = s;
  if (rapid) reader_.apply(StraightTraverse{e}); else reader_.apply(StraightFeed{e});
}

void HeidenhainWriter::arc(const ArcFeed& a) {
  flush_tool_call();
  if (reader_.plane != Plane::XY) cannot("an arc outside the XY plane (G18, G19)", "it reads CC/C in the XY plane only");
  const Pose start = reader_.position;
  Pose end = arc_end(start, a, Plane::XY);
  for (double Pose::*f : {&Pose::a, &Pose::b, &Pose::c, &Pose::u, &Pose::v, &Pose::w}) {
    if (!near(end.*f, start.*f, 1e-9)) cannot("an arc moving a rotary or U/V/W axis");
  }
  int decimals = length_decimals();
  double cx = 0, cy = 0;
  for (;; ++decimals) {
    end.x = rounded(a.first_end, decimals);
    end.y = rounded(a.second_end, decimals);
    end.z = rounded(a.axis_end_point, decimals);
    cx = rounded(a.first_axis, decimals);
    cy = rounded(a.second_axis, decimals);
    const double r1 = std::hypot(cx - start.x, cy - start.y), r2 = std::hypot(cx - end.x, cy - end.y);
    const double err = std::fabs(r1 - r2);
    if (err <= (inch_ ? 0.001 : 0.01) && err / std::max(r1, r2) <= 0.001) break;
    if (decimals >= length_decimals() + 3) cannot("an arc whose end is not on its circle");
  }
  const int turns = a.rotation < 0 ? -a.rotation : a.rotation;
  const bool cw = a.rotation < 0;
  std::string cc;
  start_path_block(cc, "CC");
  if (incremental_) {
    coordinate(cc, "IX", rounded(cx - start.x, decimals), decimals);
    coordinate(cc, "IY", rounded(cy - start.y, decimals), decimals);
  } else {
    coordinate(cc, "X", cx, decimals);
    coordinate(cc, "Y", cy, decimals);
  }
  cc += before_;
  before_.clear();
  block(cc);
  std::string s;
  if (turns <= 1) {
    s = "C";
    if (incremental_) {
      coordinate(s, "IX", rounded(end.x - start.x, decimals), decimals);
      coordinate(s, "IY", rounded(end.y - start.y, decimals), decimals);
      if (end.z != start.z) coordinate(s, "IZ", rounded(end.z - start.z, decimals), decimals);
    } else {
      coordinate(s, "X", end.x, decimals);
      coordinate(s, "Y", end.y, decimals);
      if (end.z != start.z) coordinate(s, "Z", end.z, decimals);
    }
  } else {
    // a helix of several turns: the angle swept, the height gained
    const double a0 = std::atan2(start.y - cy, start.x - cx) * kDeg;
    const double a1 = std::atan2(end.y - cy, end.x - cx) * kDeg;
    double base = cw ? a0 - a1 : a1 - a0;
    while (base <= 1e-9) base += 360.0;
    while (base > 360.0 + 1e-9) base -= 360.0;
    const double total = base + 360.0 * (turns - 1);
    s = "CP";
    coordinate(s, "IPA", rounded(cw ? -total : total, 4), 4);
    coordinate(s, "IZ", rounded(end.z - start.z, decimals), decimals);
    // where the reader will end: on the circle at the written angle
    const double r0 = std::hypot(start.x - cx, start.y - cy);
    const double at = (a0 + rounded(cw ? -total : total, 4)) / kDeg;
    end.x = cx + r0 * std::cos(at);
    end.y = cy + r0 * std::sin(at);
  }
  s += cw ? " DR-" : " DR+";
  if (!(wanted_feed_ > 0)) cannot("an arc with no feed rate");
  if (!(programmed_feed_ == wanted_feed_)) {
    append_feed(s, wanted_feed_);
    programmed_feed_ = wanted_feed_;
  }
  reader_.apply(SetFeedRate{programmed_feed_});
  path_ = s;
  ArcFeed written = a;
  written.first_end = end.x;
  written.second_end = end.y;
  written.axis_end_point = end.z;
  written.first_axis = start.x + (cx - start.x);
  written.second_axis = start.y + (cy - start.y);
  reader_.apply(written);
}

void HeidenhainWriter::action(const Call& call, const MachineState&) {
  flush_tool_call();
  const Data& d = call.data;
  if (std::holds_alternative<ProgramStop>(d)) {
    flush_before();
    flush_path();
    block("STOP");
    return;
  }
  if (std::holds_alternative<OptionalProgramStop>(d)) {
    flush_before();
    after_m("M1");
    return;
  }
  if (std::holds_alternative<PalletShuttle>(d)) cannot("a pallet change with a stop (M60)");
  if (std::holds_alternative<OrientSpindle>(d) || std::holds_alternative<WaitSpindleOrientComplete>(d)) {
    cannot("a spindle orientation (M19)");
  }
  if (std::holds_alternative<ChangeToolNumber>(d)) cannot("setting the tool in the spindle without a change (M61)");
  if (std::holds_alternative<SetToolTableEntry>(d)) cannot("writing the tool table (G10 L1)");
  if (std::holds_alternative<StraightFeed>(d) || std::holds_alternative<RigidTap>(d)) {
    cannot("spindle-synchronised motion (G33, G33.1)");
  }
  cannot(std::string(name_of(d)));
}

// Cycles 200 (G81, G82, G83), 203 (G73), 201 (G85, G89), 207 (G84, G74 with a negative pitch),
// called where the hole is (L X Y R0 FMAX M99). The surface is the R plane (Q200 set-up
// clearance 0); a G98 level above R is the 2nd set-up clearance Q204.
bool HeidenhainWriter::cycle(const Hole& hole, const MachineState& desired) {
  const CycleTag& t = hole.tag;
  const int motion = t.g_code_x10;
  if (incremental_ || t.plane != 0 || reader_.plane != Plane::XY) return false;
  const double x = length(t.x), y = length(t.y), r = length(t.r), z = length(t.z);
  const double q = length(t.q), p = rounded(t.p, 4);
  const double second = t.retract_to_r ? 0.0 : length(std::max(t.clearance, t.r) - r);
  const double depth = length(r - z);
  if (depth <= 0) return false;
  std::string number;
  std::vector<std::pair<std::string, std::string>> qs;  // Q parameter, value text, in the control's order
  NumberStyle len{length_decimals(), false, true};
  auto value = [&](double v, const NumberStyle& style) { return format_number(v, style); };
  const double feed = length(desired.feed_mm / reader_.mm_per_unit());
  int code = 810;
  double pitch = 0;
  switch (motion) {
    case 810: case 820: case 830: case 730: {
      const bool pecks = motion == 830 || motion == 730;
      number = motion == 730 ? "203 UNIVERSAL DRILLING" : "200 DRILLING";
      qs = {{"Q200", "+0"}, {"Q201", value(-depth, len)}, {"Q206", value(feed, len)},
            {"Q202", value(pecks ? q : depth, len)}, {"Q210", "+0"}, {"Q203", value(r, len)},
            {"Q204", value(second, len)}};
      if (motion == 730) {
        qs.insert(qs.end(), {{"Q212", "+0"}, {"Q213", "+1"}, {"Q205", "+0"}});
      }
      qs.push_back({"Q211", value(motion == 820 ? p : 0.0, NumberStyle{4, false, true})});
      if (motion == 730) qs.insert(qs.end(), {{"Q208", "+0"}, {"Q256", "+0.2"}});
      code = pecks && q < depth - 1e-9 ? (motion == 730 ? 730 : 830) : (motion == 820 && p > 0 ? 820 : 810);
      if (pecks && q <= 0) return false;
      break;
    }
    case 850: case 890:
      number = "201 REAMING";
      qs = {{"Q200", "+0"}, {"Q201", value(-depth, len)}, {"Q206", value(feed, len)},
            {"Q211", value(motion == 890 ? p : 0.0, NumberStyle{4, false, true})}, {"Q208", "+0"},
            {"Q203", value(r, len)}, {"Q204", value(second, len)}};
      code = motion == 890 && p > 0 ? 890 : 850;
      break;
    case 840: case 740:
      if (reader_.speed <= 0) return false;
      number = "207 RIGID TAPPING NEW";
      pitch = rounded(desired.feed_mm / reader_.mm_per_unit() / reader_.speed, 8) * (motion == 740 ? -1 : 1);
      qs = {{"Q200", "+0"}, {"Q201", value(-depth, len)}, {"Q239", value(pitch, NumberStyle{8, false, true})},
            {"Q203", value(r, len)}, {"Q204", value(second, len)}};
      code = motion;
      break;
    default:
      return false;
  }
  // what the reader will do: position at the current height, rise to the clearance, then the
  // executor's cycle with G98 (Q204 above Q200) or G99, and G80
  MachineState state = reader_;
  std::vector<Data> made;
  auto emit = [&](Data dd) {
    state.apply(dd);
    made.push_back(std::move(dd));
  };
  const bool position_xy = state.position.x != x || state.position.y != y;
  if (position_xy) {
    Pose to = state.position;
    to.x = x;
    to.y = y;
    emit(StraightTraverse{to});
  }
  const double clearance = r + second;
  if (clearance > state.position.z + 1e-9) {
    Pose to = state.position;
    to.z = clearance;
    emit(StraightTraverse{to});
  }
  const bool reverse = code == 740 && state.spindle == Direction::Clockwise;
  if (reverse) emit(StartSpindleCounterclockwise{0});
  emit(SetFeedRate{code == 840 || code == 740 ? std::fabs(pitch) * state.speed : feed});
  CycleReader c;
  c.retract_to_r = !(second > 0);
  CycleBlock b;
  b.motion = code;
  b.a = x;
  b.b = y;
  b.r = r;
  b.z = z;
  b.q = q;
  b.p = code == 820 || code == 890 ? p : 0.0;
  for (Data& dd : simulate_cycle(state, c, b)) made.push_back(std::move(dd));
  if (reverse) emit(StartSpindleClockwise{0});
  std::vector<Data> source;
  for (const Call& call : hole.calls) source.push_back(call.data);
  if (!same_motion(desired, source, reader_, made, inch_ ? 1e-5 : 1e-4)) return false;

  flush_before();
  flush_path();
  std::string definition = concat({"CYCL DEF ", number});
  for (const auto& [name, v] : qs) definition += concat({"|", name, "=", v});
  if (definition != cycle_definition_) {
    block(concat({"CYCL DEF ", number, " ~"}));
    for (std::size_t i = 0; i < qs.size(); ++i) {
      raw_line(concat({"  ", qs[i].first, "=", qs[i].second, " ;", q_parameter_name(qs[i].first),
                       i + 1 < qs.size() ? " ~" : ""}));
    }
    cycle_definition_ = definition;
  }
  if (position_xy) {
    std::string s = "L";
    coordinate(s, "X", x, length_decimals());
    coordinate(s, "Y", y, length_decimals());
    s += " R0 FMAX M99";
    block(s);
  } else {
    block("CYCL CALL");
  }
  reader_ = state;
  return true;
}

void HeidenhainWriter::begin_repeat(std::uint32_t count, double z_shift) {
  flush_tool_call();
  flush_before();
  flush_path();
  repeat_start_ = reader_.position;
  repeat_count_ = count;
  repeat_shift_ = length(z_shift);
  ++label_;
  block(concat({"LBL ", number_text(label_)}));
  incremental_ = true;
  programmed_feed_ = std::nan("");  // every copy names its feed
}

void HeidenhainWriter::end_repeat() {
  flush_path();
  Pose expected = repeat_start_;
  expected.z = length(expected.z + repeat_shift_);
  if (!near(reader_.position, expected, 1e-9)) {
    cannot("a repeated body that does not end where it began, shifted by the Z step", "the copies would not join up");
  }
  incremental_ = false;
  if (repeat_count_ > 1) block(concat({"CALL LBL ", number_text(label_), " REP", number_text(repeat_count_ - 1)}));
  reader_.position.z = length(repeat_start_.z + repeat_shift_ * repeat_count_);
}

}  // namespace

std::unique_ptr<DialectWriter> make_heidenhain_writer(const Options& o, TextOutput& out, const WriterLocation& where) {
  return std::make_unique<HeidenhainWriter>(o, out, where);
}

}  // namespace ncbridge::gcode_writer
