// Fanuc (0i/18i/30i milling): % and O number, N numbers, a decimal point on every dimension
// (a number without one counts least input increments), G4 X (seconds), cycle P in ms, G54-G59,
// G10 L2 P1-P6, G92, G43 H/G49, subprograms O.. M99 called with M98 P.. L.. for the repeat
// construct. No G43.1, G96, G64 P, M48-M53, M19, M60, M61, G10 L1, G33, U/V/W, turns of arcs.
#include "fanuc_writer.hpp"

#include <algorithm>
#include <cmath>

#include "motion_trace.hpp"

namespace ncbridge::gcode_writer {

using namespace canonical;

FanucWriter::FanucWriter(const Options& options, TextOutput& out, const WriterLocation& where, bool mach3)
    : WordAddressWriter(options, out, where), mach3_(mach3) {
  point_always_ = !mach3;
  numbered_ = options.block_numbers.value_or(!mach3);
}

void FanucWriter::write_header() {
  if (!mach3_) {
    line("%");
    std::string o = std::to_string(options_.program_number % 10000);
    while (o.size() < 4) o.insert(o.begin(), '0');
    line(concat({"O", o, " (", sanitize(options_.program_name, '(', ')'), ")"}));
  } else {
    line(concat({"(", sanitize(options_.program_name, '(', ')'), ")"}));
  }
}

void FanucWriter::write_footer(bool ended) {
  if (!mach3_ || !ended) line("%");
}

void FanucWriter::end_program(bool ended) {
  flush();
  // the repeat construct's subprograms follow the main program's end
  if (!subprograms_.empty()) {
    if (!ended) cannot("a repeated body in a program without M2/M30", "its subprograms follow the program end");
    out_.line() += subprograms_;
    if (!out_.line().empty() && out_.line().back() == '\n') out_.line().pop_back();
    out_.end_line();
  }
  write_footer(ended);
  flush();
}

void FanucWriter::write_message_line(std::string_view text) { write_comment_line(text); }

std::string_view FanucWriter::plane_word(Plane plane) const {
  if (plane != Plane::XY && plane != Plane::XZ && plane != Plane::YZ) cannot("the UV, UW or VW plane");
  return WordAddressWriter::plane_word(plane);
}

std::string FanucWriter::coord_system_word(int index) const {
  return index >= 1 && index <= 6 ? WordAddressWriter::coord_system_word(index) : std::string();
}

void FanucWriter::sync_offsets(const MachineState& d) {
  for (int index = 7; index <= 9; ++index) {
    const auto i = static_cast<std::size_t>(index);
    if (!near(reader_.g5x_mm[i], d.g5x_mm[i], 1e-9) || !near(reader_.rotation[i], d.rotation[i], 1e-9)) {
      cannot("coordinate system " + std::to_string(index) + " (G59." + std::to_string(index - 6) + ")");
    }
  }
  for (int index = 1; index <= 6; ++index) {
    const auto i = static_cast<std::size_t>(index);
    if (!near(reader_.rotation[i], d.rotation[i], 1e-9)) {
      cannot("SET_XY_ROTATION (a rotated coordinate system)", "use G68 in the program, not G10 L2 R");
    }
  }
  WordAddressWriter::sync_offsets(d);
}

void FanucWriter::sync_tool_length(const MachineState& d) {
  if (near(reader_.tool_offset_mm, d.tool_offset_mm, 1e-9)) return;
  if (!near(d.tool_offset_mm, Pose{}, 1e-12) && tool_with_offset(d.tool_offset_mm, d.tool_in_spindle) < 0) {
    cannot("a tool length offset that no tool of the tool table has (G43.1)", "give the tool list the program runs with");
  }
  WordAddressWriter::sync_tool_length(d);
}

void FanucWriter::sync_spindle_mode(const MachineState& d) {
  if (!near(reader_.css_maximum, d.css_maximum, 1e-9)) cannot("constant surface speed (G96/G97)");
}

void FanucWriter::sync_control(const MachineState& d) {
  if (d.control == MotionControlMode::ExactStop) cannot("exact stop mode (G61.1)");
  sync_control_without_tolerance(d);
}

void FanucWriter::sync_overrides(const MachineState& d) {
  if (reader_.feed_override != d.feed_override || reader_.speed_override != d.speed_override ||
      reader_.adaptive_feed != d.adaptive_feed || reader_.feed_hold != d.feed_hold) {
    cannot("switching feed or speed overrides (M48-M53)");
  }
}

void FanucWriter::write_dwell(double seconds) {
  std::string& s = put(Slot::Dwell);
  s += "G4 ";
  // Fanuc: X in seconds; Mach3: P in seconds
  append_plain(s, mach3_ ? 'P' : 'X', seconds);
}

void FanucWriter::write_turns(std::string&, int turns) {
  cannot("an arc of " + std::to_string(turns) + " turns (P)", "its arcs turn at most once");
}

bool FanucWriter::axis_supported(char letter) const { return letter != 'U' && letter != 'V' && letter != 'W'; }

void FanucWriter::write_other_action(const Call& call, const MachineState& desired) {
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

bool FanucWriter::has_cycle(int motion) const {
  switch (motion) {
    case 730: case 810: case 820: case 830: case 840: case 850: case 860: case 880: case 890: return true;
    case 740: return !mach3_;  // Fanuc G74: left-hand tapping; Mach3 has none
    default: return false;     // G87/G76: Fanuc's are other cycles than LinuxCNC's
  }
}

// fanuc.yaml / mach3.yaml cycle_words: Fanuc's G86 has no P
bool FanucWriter::reads_cycle_dwell(int motion) const {
  if (mach3_) return motion == 820 || motion == 840 || motion == 860 || motion == 880 || motion == 890;
  return motion == 740 || motion == 820 || motion == 840 || motion == 880 || motion == 890;
}

void FanucWriter::append_cycle_dwell(std::string& s, double seconds) {
  s.push_back(' ');
  if (mach3_) {
    append_plain(s, 'P', seconds);
    return;
  }
  // P in milliseconds, without a decimal point
  const double ms = seconds * 1000.0;
  if (std::fabs(ms - std::round(ms)) < 1e-6) {
    append_int(s, "P", static_cast<long long>(std::llround(ms)));
  } else {
    cannot("a cycle dwell of " + format_number(seconds, NumberStyle{6, false, false}) + " s", "P counts whole milliseconds");
  }
}

bool FanucWriter::cycle(const Hole& hole, const MachineState& desired) {
  if (!is_cycle_motion(cycle_.motion)) fanuc_initial_ = reader_.position.z;
  const bool oriented = std::any_of(hole.calls.begin(), hole.calls.end(), [](const Call& c) {
    return std::holds_alternative<OrientSpindle>(c.data);
  });
  if (!mach3_ && oriented && (hole.tag.g_code_x10 == 860 || hole.tag.g_code_x10 == 870)) {
    return fanuc_boring(hole, desired);
  }
  return WordAddressWriter::cycle(hole, desired);
}

bool FanucWriter::fanuc_boring(const Hole& hole, const MachineState& desired) {
  const CycleTag& t = hole.tag;
  const bool fine = t.g_code_x10 == 860;  // the front-end tags its G76 as the boring it is, G87 as 870
  if (incremental_ || t.plane != 0 || reader_.plane != Plane::XY) return false;
  const double x = length(t.x), y = length(t.y), r = length(t.r), z = length(t.z), q = length(std::fabs(t.q));
  const double ms = std::round(t.p * 1000.0);
  if (std::fabs(t.p * 1000.0 - ms) > 1e-6) return false;
  const double dwell = ms / 1000.0;
  // the shift at the bottom: fanuc.yaml boring_shift_direction 0, +X (parameter 5101)
  const double sx = q, sy = 0;
  MachineState s = reader_;
  const Direction spindle = s.spindle;
  if (spindle == Direction::Stopped) return false;
  std::vector<Data> made;
  auto move = [&](bool feed, double px, double py, double pz) {
    Pose to = s.position;
    to.x = px;
    to.y = py;
    to.z = pz;
    Data d = feed ? Data{StraightFeed{to}} : Data{StraightTraverse{to}};
    s.apply(d);
    made.push_back(std::move(d));
  };
  auto emit = [&](Data d) {
    s.apply(d);
    made.push_back(std::move(d));
  };
  auto oriented_stop = [&] {
    emit(StopSpindleTurning{0});
    emit(OrientSpindle{0, 0.0, 0});
  };
  auto spindle_on = [&] {
    if (spindle == Direction::Counterclockwise) emit(StartSpindleCounterclockwise{0}); else emit(StartSpindleClockwise{0});
  };
  const double initial = fanuc_initial_;
  if (fine) {
    if (r < z) return false;
    const double clear = t.retract_to_r ? r : std::max(initial, r);
    const Pose at = s.position;
    if (at.z < r) move(false, at.x, at.y, r);
    const double level = std::max(at.z, r);
    move(false, x, y, level);
    if (level > r) move(false, x, y, r);
    move(true, x, y, z);
    if (dwell > 0) emit(Dwell{dwell});
    oriented_stop();
    move(false, x + sx, y + sy, z);
    move(false, x + sx, y + sy, clear);
    move(false, x, y, clear);
    spindle_on();
  } else {
    const double level = s.position.z;
    if (r > z || initial < z || level < z) return false;
    move(false, x, y, level);
    oriented_stop();
    move(false, x + sx, y + sy, level);
    move(false, x + sx, y + sy, r);
    move(false, x, y, r);
    spindle_on();
    move(true, x, y, z);
    if (dwell > 0) emit(Dwell{dwell});
    oriented_stop();
    move(false, x + sx, y + sy, z);
    move(false, x + sx, y + sy, initial);
    move(false, x, y, initial);
    spindle_on();
  }
  std::vector<Data> source;
  for (const Call& c : hole.calls) source.push_back(c.data);
  if (!same_motion(desired, source, reader_, made, reader_.units == Units::Inches ? 1e-5 : 1e-4)) return false;
  if (fine && (cycle_.retract_to_r != t.retract_to_r || !retract_written_)) {
    put(Slot::Retract) += t.retract_to_r ? "G99" : "G98";
    cycle_.retract_to_r = t.retract_to_r;
    retract_written_ = true;
  }
  std::string& b = put(Slot::Motion);
  b += fine ? "G76 " : "G87 ";
  append(b, 'X', x);
  b.push_back(' ');
  append(b, 'Y', y);
  b.push_back(' ');
  append(b, 'Z', z);
  b.push_back(' ');
  append(b, 'R', r);
  b.push_back(' ');
  append(b, 'Q', q);
  append_int(b, " P", static_cast<long long>(ms));
  flush();
  reader_ = s;
  note_other_motion(cycle_, fine ? 761 : 871);  // the front-end stays in the cycle; the executor ran moves
  return true;
}

void FanucWriter::write_repeat_begin(std::uint32_t count) {
  ++repeat_label_;
  const std::uint32_t number = options_.program_number % 10000 + static_cast<std::uint32_t>(repeat_label_);
  std::string& s = put(Slot::NonModal);
  append_int(s, "M98 P", number);
  append_int(s, " L", count);
  flush();
  sub_out_ = std::make_unique<TextOutput>([this](std::string_view piece) { subprograms_.append(piece); });
  target_ = sub_out_.get();
  std::string o = std::to_string(number);
  while (o.size() < 4) o.insert(o.begin(), '0');
  line(concat({"O", o}));
  put(Slot::Distance) += "G91";
  flush();
}

void FanucWriter::write_repeat_end() {
  put(Slot::Distance) += "G90";
  flush();
  put(Slot::Stop) += "M99";
  flush();
  sub_out_->flush();
  target_ = &out_;
  sub_out_.reset();
}

std::unique_ptr<DialectWriter> make_fanuc_writer(const Options& o, TextOutput& out, const WriterLocation& where) {
  return std::make_unique<FanucWriter>(o, out, where, false);
}

}  // namespace ncbridge::gcode_writer
