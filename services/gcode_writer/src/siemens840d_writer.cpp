// SINUMERIK 840D (sl), as services/interpreter/src/siemens840d/ reads it: `;` comments,
// MSG("..."), N numbers, G710/G700, G54-G57, T.. M6 then D1 (the length of the tool in the
// spindle) or D0, G60/G64, G4 F (seconds), TURN= for arcs of several turns in G17, the drilling
// cycles CYCLE81-CYCLE89 after positioning, REPEAT ... UNTIL for the repeat construct. No G10
// (settable offsets are the machine's data), G92, XY rotation, G96, G61.1, G64 tolerance,
// overrides, M19, M60, M61, tool table writes, G33, U/V/W, G74.
#include <cmath>

#include "motion_trace.hpp"
#include "word_address_writer.hpp"

namespace ncbridge::gcode_writer {

using namespace canonical;

namespace {

std::string quoted_text(std::string_view text) {
  std::string s;
  for (char c : text) s.push_back(c == '"' ? '\'' : c == '\n' || c == '\r' ? ' ' : c);
  return s;
}

class Siemens840dWriter final : public WordAddressWriter {
 public:
  Siemens840dWriter(const Options& options, TextOutput& out, const WriterLocation& where)
      : WordAddressWriter(options, out, where) {
    numbered_ = options.block_numbers.value_or(true);
  }

  bool arcs_turn_more_than_once() const override { return reader_.plane == Plane::XY; }

  bool cycle(const Hole& hole, const MachineState& desired) override;

 protected:
  void write_header() override {
    line(concat({"; ", quoted_text(options_.program_name), " (SINUMERIK 840D, written by ncbridge)"}));
  }
  void write_safety_block(const MachineState& desired) override {
    std::string& s = put(Slot::Plane);
    s += "G17 ";
    s += units_word(desired.units);
    s += " G40 G90 G94";
    flush();
    reader_.apply(SetSelectPlaneXy());
    reader_.apply(UseLengthUnits{desired.units});
    reader_.apply(SetFeedMode{0, 0});
    reader_.apply(SetFeedRate{0});
  }
  void write_footer(bool ended) override {
    if (!ended) cannot("a program that ends at its end of tape (no M2/M30)", "a part program ends with M30 or M2");
  }
  void write_comment_line(std::string_view text) override { line(concat({"; ", quoted_text(text)})); }
  void write_message_line(std::string_view text) override { line(concat({"MSG(\"", quoted_text(text), "\")"})); }
  std::string_view units_word(Units units) const override { return units == Units::Inches ? "G700" : "G710"; }
  std::string_view plane_word(Plane plane) const override {
    if (plane != Plane::XY && plane != Plane::XZ && plane != Plane::YZ) cannot("the UV, UW or VW plane");
    return WordAddressWriter::plane_word(plane);
  }
  std::string coord_system_word(int index) const override {
    return index >= 1 && index <= 4 ? WordAddressWriter::coord_system_word(index) : std::string();
  }
  void sync_offsets(const MachineState& d) override {
    for (int index = 1; index <= 9; ++index) {
      const auto i = static_cast<std::size_t>(index);
      if (!near(reader_.g5x_mm[i], d.g5x_mm[i], 1e-9)) {
        cannot("setting the values of a work offset (G10 L2, G10 L20)", "the settable zero offsets are machine data");
      }
      if (!near(reader_.rotation[i], d.rotation[i], 1e-9)) cannot("SET_XY_ROTATION (a rotated work offset)");
    }
    if (!near(reader_.g92_mm, d.g92_mm, 1e-9)) cannot("a G92 offset", "G92 is a spindle speed limit on a SINUMERIK");
    WordAddressWriter::sync_offsets(d);
  }
  void sync_tool_length(const MachineState& d) override {
    if (near(reader_.tool_offset_mm, d.tool_offset_mm, 1e-9)) return;
    if (near(d.tool_offset_mm, Pose{}, 1e-12)) {
      put(Slot::ToolLength) += "D0";
      reader_.apply(UseToolLengthOffset{Pose{}});
      return;
    }
    const Pose* spindle = tool_offset_of(reader_.tool_in_spindle);
    if (spindle == nullptr || !near(*spindle, d.tool_offset_mm, 1e-9)) {
      cannot("a tool length offset other than the length of the tool in the spindle (D1)");
    }
    put(Slot::ToolLength) += "D1";
    reader_.apply(UseToolLengthOffset{from_mm(*spindle, reader_.mm_per_unit())});
  }
  void sync_spindle_mode(const MachineState& d) override {
    if (!near(reader_.css_maximum, d.css_maximum, 1e-9)) cannot("constant surface speed (G96/G97)");
  }
  void sync_control(const MachineState& desired) override {
    if (desired.control == MotionControlMode::ExactStop) cannot("exact stop mode (G61.1)");
    sync_control_without_tolerance(desired);
  }
  // G60 (exact stop, modal) is the executor's exact path; G64 its continuous mode.
  std::string_view control_word(MotionControlMode mode) const override {
    return mode == MotionControlMode::ExactPath ? "G60" : "G64";
  }
  void sync_overrides(const MachineState& d) override {
    if (reader_.feed_override != d.feed_override || reader_.speed_override != d.speed_override ||
        reader_.adaptive_feed != d.adaptive_feed || reader_.feed_hold != d.feed_hold) {
      cannot("switching feed or speed overrides (M48-M53)");
    }
  }
  void write_dwell(double seconds) override {
    std::string& s = put(Slot::Dwell);
    s += "G4 ";
    append_plain(s, 'F', seconds);
  }
  void write_turns(std::string& s, int turns) override { append_int(s, " TURN=", turns - 1); }
  bool axis_supported(char letter) const override { return letter != 'U' && letter != 'V' && letter != 'W'; }
  void write_other_action(const Call& call, const MachineState& desired) override {
    const Data& d = call.data;
    if (std::holds_alternative<ProgramStop>(d) || std::holds_alternative<OptionalProgramStop>(d)) {
      WordAddressWriter::write_other_action(call, desired);
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
    WordAddressWriter::write_other_action(call, desired);
  }
  void write_repeat_begin(std::uint32_t count) override {
    ++repeat_label_;
    counter_ = concat({"R", number_text(89 + repeat_label_)});
    line(concat({counter_, "=0"}));
    line("REPEAT");
    put(Slot::Distance) += "G91";
    flush();
    count_ = count;
  }
  void write_repeat_end() override {
    put(Slot::Distance) += "G90";
    flush();
    line(concat({counter_, "=", counter_, "+1"}));
    line(concat({"UNTIL ", counter_, "==", number_text(count_)}));
  }

 private:
  static Data SetSelectPlaneXy() { return SelectPlane{Plane::XY}; }
  std::string counter_;
  std::uint32_t count_ = 0;
};

// CYCLE8x(RTP, RFP, SDIS, DP, ...) at the current position: the reader rapids to RTP first when
// the tool is elsewhere, drills with G98 from there (RTP is the G98 level) and cancels (G80).
// Positioned first at the current height (X Y), as the source positioned; R is RFP (+ SDIS 0).
bool Siemens840dWriter::cycle(const Hole& hole, const MachineState& desired) {
  const CycleTag& t = hole.tag;
  const int motion = t.g_code_x10;
  if (incremental_ || t.plane != 0 || reader_.plane != Plane::XY) return false;
  const char* name = nullptr;
  switch (motion) {
    case 810: name = "CYCLE81"; break;
    case 820: name = "CYCLE82"; break;
    case 730: case 830: name = "CYCLE83"; break;
    case 840: name = "CYCLE84"; break;
    case 850: name = "CYCLE85"; break;
    case 860: name = "CYCLE86"; break;
    case 880: name = "CYCLE88"; break;
    case 890: name = "CYCLE89"; break;
    default: return false;
  }
  const double x = length(t.x), y = length(t.y), r = length(t.r), z = length(t.z);
  const double rtp = t.retract_to_r ? r : length(t.clearance);
  const double q = length(t.q);
  const double p = rounded(t.p, 4);
  if ((motion == 730 || motion == 830) && q <= 0) return false;
  if (rtp < r) return false;
  MachineState state = reader_;
  std::vector<Data> made;
  auto emit = [&](Data d) {
    state.apply(d);
    made.push_back(std::move(d));
  };
  const bool position_xy = state.position.x != x || state.position.y != y;
  if (position_xy) {
    Pose to = state.position;
    to.x = x;
    to.y = y;
    emit(StraightTraverse{to});
  }
  double pitch = 0;
  if (motion == 840) {
    if (state.speed <= 0) return false;
    pitch = rounded(desired.feed_mm / state.mm_per_unit() / state.speed, 8);
    emit(SetFeedRate{pitch * state.speed});
  }
  if (std::fabs(state.position.z - rtp) > 1e-9) {
    Pose to = state.position;
    to.z = rtp;
    emit(StraightTraverse{to});
  }
  CycleReader c;
  c.retract_to_r = false;
  CycleBlock block;
  block.motion = motion;
  block.a = x;
  block.b = y;
  block.r = r;
  block.z = z;
  block.q = q;
  block.p = motion == 820 || motion == 860 || motion == 880 || motion == 890 ? p : 0.0;
  for (Data& d : simulate_cycle(state, c, block)) made.push_back(std::move(d));
  std::vector<Data> source;
  for (const Call& call : hole.calls) source.push_back(call.data);
  if (!same_motion(desired, source, reader_, made, reader_.units == Units::Inches ? 1e-5 : 1e-4)) return false;

  if (position_xy) {
    std::string& s = put(Slot::Motion);
    motion_word(s, 0);
    if (!s.empty() && s.back() != ' ') s.push_back(' ');
    append(s, 'X', x);
    s.push_back(' ');
    append(s, 'Y', y);
    flush();
    cycle_.motion = 0;
  }
  // the positional parameters (dialects/siemens840d.yaml): RTP RFP SDIS DP, then per cycle
  std::vector<std::string> args(4);
  NumberStyle n = style_;
  n.decimals = length_decimals();
  args[0] = format_number(rtp, n);
  args[1] = format_number(r, n);
  args[2].assign(1, '0');
  args[3] = format_number(z, n);
  auto set = [&](std::size_t index, std::string value) {
    if (args.size() <= index) args.resize(index + 1);
    args[index] = std::move(value);
  };
  switch (motion) {
    case 820: case 860: case 880: case 890: set(5, format_number(p, NumberStyle{4, false, false})); break;  // DTB
    case 730: case 830:
      set(6, format_number(q, n));      // FDPR: the first depth, from RFP
      set(11, motion == 730 ? "0" : "1");  // VARI: chip breaking (G73) or removal (G83)
      break;
    case 840: set(8, format_number(pitch, NumberStyle{8, false, false})); break;  // PIT
    default: break;
  }
  std::string s = name;
  s.push_back('(');
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (i > 0) s += ", ";
    s += args[i];
  }
  s.push_back(')');
  put(Slot::NonModal) += s;
  flush();
  reader_ = state;
  return true;
}

}  // namespace

std::unique_ptr<DialectWriter> make_siemens840d_writer(const Options& o, TextOutput& out, const WriterLocation& where) {
  return std::make_unique<Siemens840dWriter>(o, out, where);
}

}  // namespace ncbridge::gcode_writer
