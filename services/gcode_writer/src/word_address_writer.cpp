#include "word_address_writer.hpp"

#include <cmath>
#include <numbers>

#include "motion_trace.hpp"

namespace ncbridge::gcode_writer {

using namespace canonical;

namespace {

struct AxisField {
  char letter;
  double Pose::*field;
  bool linear;
};
constexpr AxisField kAxes[9] = {{'X', &Pose::x, true}, {'Y', &Pose::y, true}, {'Z', &Pose::z, true},
                                {'A', &Pose::a, false}, {'B', &Pose::b, false}, {'C', &Pose::c, false},
                                {'U', &Pose::u, true}, {'V', &Pose::v, true}, {'W', &Pose::w, true}};

struct PlaneLetters {
  double Pose::*first;
  double Pose::*second;
  double Pose::*normal;
  char first_offset, second_offset;
};

PlaneLetters plane_letters(Plane plane) {
  switch (plane) {
    case Plane::YZ: return {&Pose::y, &Pose::z, &Pose::x, 'J', 'K'};
    case Plane::XZ: return {&Pose::z, &Pose::x, &Pose::y, 'K', 'I'};
    default: return {&Pose::x, &Pose::y, &Pose::z, 'I', 'J'};
  }
}

// LinuxCNC's check that the end of an IJK arc lies on its circle (arcs.cpp).
bool arc_radius_ok(double c1, double c2, double s1, double s2, double e1, double e2, bool inch) {
  const double r1 = std::hypot(c1 - s1, c2 - s2), r2 = std::hypot(c1 - e1, c2 - e2);
  const double min_radius = inch ? 0.00005 : 0.00127;
  if (r1 < min_radius || r2 < min_radius) return false;
  const double abs_err = std::fabs(r1 - r2);
  return abs_err <= (inch ? 0.001 : 0.01) && abs_err / std::max(r1, r2) <= 0.001;
}

}  // namespace

std::string sanitize(std::string_view text, char open, char close) {
  std::string s;
  s.reserve(text.size());
  for (char c : text) {
    if (c == '\n' || c == '\r') c = ' ';
    if (c == open) c = '[';
    if (c == close) c = ']';
    s.push_back(c);
  }
  return s;
}

WordAddressWriter::WordAddressWriter(const Options& options, TextOutput& out, const WriterLocation& where)
    : DialectWriter(options, out, where), target_(&out) {
  for (const setup::Tool& t : options.tools.tools()) {
    Pose offset;
    offset.x = t.x_offset;
    offset.z = t.length;
    tool_offsets_mm_[t.number] = offset;
  }
  numbered_ = options.block_numbers.value_or(false);
}

// ---------------------------------------------------------------------------------------------
// blocks

std::string& WordAddressWriter::put(Slot slot) {
  const int s = static_cast<int>(slot);
  if ((used_ & (1u << s)) != 0 || s < last_slot_) flush();
  std::string& text = slot_text_[s];
  if (!text.empty()) text.push_back(' ');
  used_ |= 1u << s;
  last_slot_ = s;
  block_open_ = true;
  return text;
}

void WordAddressWriter::flush() {
  if (!block_open_) return;
  static constexpr Slot kDisplay[] = {
      Slot::Comment, Slot::Dwell, Slot::Plane, Slot::Units, Slot::FeedMode, Slot::SpindleMode, Slot::ToolLength,
      Slot::CoordSystem, Slot::Control, Slot::Distance, Slot::Retract, Slot::NonModal, Slot::Motion, Slot::Feed,
      Slot::Speed, Slot::Tool, Slot::ToolChange, Slot::Spindle, Slot::Coolant, Slot::Override, Slot::Stop};
  std::string& out = target_->line();
  if (numbered_) {
    block_number_ += options_.block_number_step;
    if (block_number_ > 99999) block_number_ = options_.block_number_step;
    append_int(out, "N", static_cast<long long>(block_number_));
  }
  for (Slot slot : kDisplay) {
    std::string& text = slot_text_[static_cast<int>(slot)];
    if (text.empty()) continue;
    if (!out.empty() && out.back() != '\n') out.push_back(' ');
    out += text;
    text.clear();
  }
  target_->end_line();
  used_ = 0;
  last_slot_ = -1;
  block_open_ = false;
}

void WordAddressWriter::line(std::string_view text) {
  flush();
  target_->line() += text;
  target_->end_line();
}

void WordAddressWriter::append(std::string& s, char letter, double value) {
  s.push_back(letter);
  style_.decimals = length_decimals();
  style_.point_always = point_always_;
  append_number(s, value, style_);
}

void WordAddressWriter::append_feed(std::string& s, char letter, double value) { append(s, letter, value); }

void WordAddressWriter::append_plain(std::string& s, char letter, double value) {
  s.push_back(letter);
  NumberStyle plain;
  plain.decimals = 4;
  plain.point_always = point_always_;
  append_number(s, value, plain);
}

Pose WordAddressWriter::rounded_pose(const Pose& p) const {
  Pose r = p;
  for (const AxisField& a : kAxes) r.*a.field = a.linear ? length(p.*a.field) : rounded(p.*a.field, 4);
  return r;
}

// ---------------------------------------------------------------------------------------------
// program frame

void WordAddressWriter::begin_program(const MachineState& desired) {
  write_header();
  write_safety_block(desired);
}

// G17 G21 G40 G49 G80 G90 G94: what every program states first.
void WordAddressWriter::write_safety_block(const MachineState& desired) {
  put(Slot::FeedMode) += "G94";
  put(Slot::Plane) += "G17";
  std::string& units = put(Slot::Units);
  units += units_word(desired.units);
  units += " G40";
  put(Slot::ToolLength) += "G49";
  put(Slot::Distance) += "G90";
  put(Slot::Motion) += "G80";
  flush();
  reader_.apply(canonical::SetFeedMode{0, 0});
  reader_.apply(canonical::SetFeedRate{0});
  reader_.apply(canonical::SelectPlane{canonical::Plane::XY});
  reader_.apply(canonical::UseLengthUnits{desired.units});
  reader_.apply(canonical::UseToolLengthOffset{canonical::Pose{}});
}

void WordAddressWriter::write_header() {
  line("%");
  line(concat({"(", sanitize(options_.program_name, '(', ')'), ")"}));
}

void WordAddressWriter::write_footer(bool) { line("%"); }

void WordAddressWriter::end_program(bool ended) {
  flush();
  write_footer(ended);
  flush();
}

void WordAddressWriter::program_end(bool rewind) {
  leave_cycles();
  put(Slot::Stop) += rewind ? "M30" : "M2";
  flush();
}

void WordAddressWriter::write_comment_line(std::string_view text) { line(concat({"(", sanitize(text, '(', ')'), ")"})); }

void WordAddressWriter::write_message_line(std::string_view text) { line(concat({"(MSG,", sanitize(text, '(', ')'), ")"})); }

void WordAddressWriter::comment(std::string_view text) { write_comment_line(text); }

void WordAddressWriter::message(std::string_view text) { write_message_line(text); }

// ---------------------------------------------------------------------------------------------
// state

std::string_view WordAddressWriter::units_word(Units units) const { return units == Units::Inches ? "G20" : "G21"; }

std::string_view WordAddressWriter::plane_word(Plane plane) const {
  switch (plane) {
    case Plane::XY: return "G17";
    case Plane::XZ: return "G18";
    case Plane::YZ: return "G19";
    case Plane::UV: return "G17.1";
    case Plane::UW: return "G18.1";
    case Plane::VW: return "G19.1";
  }
  return "G17";
}

std::string WordAddressWriter::coord_system_word(int index) const {
  static const char* const kWords[10] = {"", "G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3"};
  return index >= 1 && index <= 9 ? kWords[index] : "";
}

const Pose* WordAddressWriter::tool_offset_of(int tool) const {
  auto it = tool_offsets_mm_.find(tool);
  return it == tool_offsets_mm_.end() ? nullptr : &it->second;
}

int WordAddressWriter::tool_with_offset(const Pose& offset_mm, int prefer) const {
  if (const Pose* p = tool_offset_of(prefer); p != nullptr && near(*p, offset_mm, 1e-9)) return prefer;
  for (const auto& [tool, offset] : tool_offsets_mm_) {
    if (tool != 0 && near(offset, offset_mm, 1e-9)) return tool;
  }
  return -1;
}

void WordAddressWriter::sync(const MachineState& d, unsigned need) {
  if ((need & (kFrame | kUnits)) != 0 && reader_.units != d.units) {
    flush();
    put(Slot::Units) += units_word(d.units);
    flush();
    reader_.apply(UseLengthUnits{d.units});
  }
  if ((need & kFrame) != 0 &&
      (d.frame_generation != synced_desired_frame_ || reader_.frame_generation != synced_reader_frame_)) {
    sync_offsets(d);
    sync_tool_length(d);
    synced_desired_frame_ = d.frame_generation;
    synced_reader_frame_ = reader_.frame_generation;
  }
  if ((need & kFeed) != 0) {
    if (reader_.feed_reference != d.feed_reference) cannot("SET_FEED_REFERENCE(CANON_WORKPIECE)", "feeds are along the tool path");
    if (reader_.feed_mode != d.feed_mode) {
      put(Slot::FeedMode) += d.feed_mode == 1 ? "G95" : "G94";
      reader_.apply(SetFeedMode{0, d.feed_mode});
      reader_.apply(SetFeedRate{0});
    }
  }
  if ((need & kActuators) != 0) sync_spindle_mode(d);
  if ((need & kFeed) != 0) {
    const double k = reader_.mm_per_unit();
    const double f = length(d.feed_mm / k);
    if (!near(f * k, reader_.feed_mm, 1e-9 * (1 + std::fabs(f)))) {
      if (f < 0) cannot("a negative feed rate");
      append_feed(put(Slot::Feed), 'F', f);
      reader_.apply(SetFeedRate{f});
    }
  }
  if ((need & kActuators) != 0) {
    const double s = rounded(d.speed, 4);
    if (s != reader_.speed) {
      std::string& text = put(Slot::Speed);
      text.push_back('S');
      append_number(text, s, NumberStyle{4, false, false});  // never "S3000." (an integer address)
      reader_.apply(SetSpindleSpeed{0, s});
    }
  }
  if ((need & kToolSelect) != 0 && d.selected_tool >= 0 && d.selected_tool != reader_.selected_tool) {
    append_int(put(Slot::Tool), "T", d.selected_tool);
    reader_.apply(SelectTool{d.selected_tool});
  }
  if ((need & kActuators) != 0) {
    if (d.spindle != reader_.spindle) {
      put(Slot::Spindle) += d.spindle == Direction::Clockwise ? "M3" : d.spindle == Direction::Counterclockwise ? "M4" : "M5";
      if (d.spindle == Direction::Clockwise) reader_.apply(StartSpindleClockwise{0});
      else if (d.spindle == Direction::Counterclockwise) reader_.apply(StartSpindleCounterclockwise{0});
      else reader_.apply(StopSpindleTurning{0});
    }
    if ((reader_.mist && !d.mist) || (reader_.flood && !d.flood)) {
      put(Slot::Coolant) += "M9";
      reader_.apply(MistOff{});
      reader_.apply(FloodOff{});
    }
    if (d.mist && !reader_.mist) {
      put(Slot::Coolant) += "M7";
      reader_.apply(MistOn{});
    }
    if (d.flood && !reader_.flood) {
      put(Slot::Coolant) += "M8";
      reader_.apply(FloodOn{});
    }
  }
  if ((need & kFeed) != 0) sync_overrides(d);
  if ((need & kPlane) != 0 && reader_.plane != d.plane) {
    put(Slot::Plane) += plane_word(d.plane);
    reader_.apply(SelectPlane{d.plane});
  }
  if ((need & kPath) != 0) sync_control(d);
}

void WordAddressWriter::sync_offsets(const MachineState& d) {
  const double k = reader_.mm_per_unit();
  for (int index = 1; index <= 9; ++index) {
    const auto i = static_cast<std::size_t>(index);
    const bool values = !near(reader_.g5x_mm[i], d.g5x_mm[i], 1e-9);
    const bool rotation = !near(reader_.rotation[i], d.rotation[i], 1e-9);
    if (!values && !rotation) continue;
    flush();
    std::string& s = put(Slot::NonModal);
    append_int(s, "G10 L2 P", index);
    Pose written = reader_.g5x_mm[i];
    for (const AxisField& a : kAxes) {
      const double want = d.g5x_mm[i].*a.field;
      if (near(written.*a.field, want, 1e-9)) continue;
      if (!a.linear) {
        const double v = rounded(want, 4);
        s.push_back(' ');
        append_plain(s, a.letter, v);
        written.*a.field = v;
      } else {
        const double v = length(want / k);
        s.push_back(' ');
        append(s, a.letter, v);
        written.*a.field = v * k;
      }
    }
    double new_rotation = reader_.rotation[i];
    if (rotation) {
      new_rotation = rounded(d.rotation[i], 4);
      s.push_back(' ');
      append_plain(s, 'R', new_rotation);
    }
    flush();
    if (index == reader_.coord_system) {
      reader_.apply(SetG5xOffset{index, from_mm(written, k)});
      reader_.apply(SetXyRotation{new_rotation});
    } else {
      reader_.g5x_mm[i] = written;
      reader_.rotation[i] = new_rotation;
    }
  }
  if (reader_.coord_system != d.coord_system) {
    const std::string word = coord_system_word(d.coord_system);
    if (word.empty()) cannot("coordinate system " + std::to_string(d.coord_system) + " (G5x)");
    put(Slot::CoordSystem) += word;
    const int index = d.coord_system;
    reader_.apply(SetG5xOffset{index, from_mm(reader_.g5x_mm[static_cast<std::size_t>(index)], k)});
    reader_.apply(SetG92Offset{from_mm(reader_.g92_mm, k)});
    reader_.apply(SetXyRotation{reader_.rotation[static_cast<std::size_t>(index)]});
  }
  if (!near(reader_.g92_mm, d.g92_mm, 1e-9)) {
    flush();
    if (near(d.g92_mm, Pose{}, 1e-12) && has_g92_clear()) {
      put(Slot::NonModal) += "G92.1";
      flush();
      reader_.apply(SetG92Offset{Pose{}});
      return;
    }
    // G92 makes the current position read the given values: v = position + (g92 now - g92 wanted)
    std::string& s = put(Slot::NonModal);
    s += "G92";
    Pose g92 = reader_.g92_mm;
    for (const AxisField& a : kAxes) {
      const double now = reader_.g92_mm.*a.field, want = d.g92_mm.*a.field;
      if (near(now, want, 1e-9)) continue;
      const double scale = a.linear ? k : 1.0;
      const double v = a.linear ? length(reader_.position.*a.field + (now - want) / k)
                                : rounded(reader_.position.*a.field + (now - want), 4);
      s.push_back(' ');
      if (a.linear) append(s, a.letter, v); else append_plain(s, a.letter, v);
      g92.*a.field = reader_.position.*a.field * scale + now - v * scale;
    }
    flush();
    reader_.apply(SetG92Offset{from_mm(g92, k)});
  }
}

void WordAddressWriter::sync_tool_length(const MachineState& d) {
  if (near(reader_.tool_offset_mm, d.tool_offset_mm, 1e-9)) return;
  const double k = reader_.mm_per_unit();
  if (near(d.tool_offset_mm, Pose{}, 1e-12)) {
    put(Slot::ToolLength) += "G49";
    reader_.apply(UseToolLengthOffset{Pose{}});
    return;
  }
  const int tool = tool_with_offset(d.tool_offset_mm, d.tool_in_spindle);
  if (tool > 0) {
    append_int(put(Slot::ToolLength), "G43 H", tool);
    reader_.apply(UseToolLengthOffset{from_mm(*tool_offset_of(tool), k)});
    return;
  }
  // no tool of the table has this length: a dynamic offset
  flush();
  std::string& s = put(Slot::ToolLength);
  s += "G43.1";
  Pose written;
  for (const AxisField& a : kAxes) {
    // every axis whose offset is not zero now or after: LinuxCNC keeps the offset of an axis
    // G43.1 does not name, ncbridge's reader zeroes it; written, both agree
    const double want = d.tool_offset_mm.*a.field;
    if (want == 0 && reader_.tool_offset_mm.*a.field == 0) continue;
    const double v = a.linear ? length(want / k) : rounded(want, 4);
    s.push_back(' ');
    if (a.linear) append(s, a.letter, v); else append_plain(s, a.letter, v);
    written.*a.field = v;
  }
  flush();
  reader_.apply(UseToolLengthOffset{written});
}

void WordAddressWriter::sync_spindle_mode(const MachineState& d) {
  if (near(reader_.css_maximum, d.css_maximum, 1e-9)) return;
  std::string& s = put(Slot::SpindleMode);
  if (d.css_maximum == 0) {
    s += "G97";
  } else {
    s += "G96";
    if (d.css_maximum < 1e29) {
      s.push_back(' ');
      append(s, 'D', d.css_maximum);
    }
  }
  reader_.apply(SetSpindleMode{0, d.css_maximum});
}

std::string_view WordAddressWriter::control_word(MotionControlMode mode) const {
  return mode == MotionControlMode::ExactPath ? "G61" : mode == MotionControlMode::ExactStop ? "G61.1" : "G64";
}

void WordAddressWriter::sync_control(const MachineState& d) {
  sync_control_mode(d.control, d.tolerance, d.naive_tolerance);
}

void WordAddressWriter::sync_control_mode(MotionControlMode mode, double tolerance, double naive) {
  const bool same_mode = reader_.control == mode;
  const bool same_tolerance = mode != MotionControlMode::Continuous ||
                              (near(reader_.tolerance, tolerance, 1e-9) && near(reader_.naive_tolerance, naive, 1e-9));
  if (same_mode && same_tolerance) return;
  std::string& s = put(Slot::Control);
  switch (mode) {
    case MotionControlMode::ExactPath:
      s += control_word(mode);
      reader_.apply(SetMotionControlMode{MotionControlMode::ExactPath, 0});
      return;
    case MotionControlMode::ExactStop:
      s += control_word(mode);
      reader_.apply(SetMotionControlMode{MotionControlMode::ExactStop, 0});
      return;
    case MotionControlMode::Continuous: {
      s += control_word(mode);
      const double p = length(tolerance), q = length(naive);
      if (p != 0 || q != 0) {
        s.push_back(' ');
        append(s, 'P', p);
      }
      if (q != p) {
        s.push_back(' ');
        append(s, 'Q', q);
      }
      reader_.apply(SetMotionControlMode{MotionControlMode::Continuous, p});
      reader_.apply(SetNaivecamTolerance{q});
      return;
    }
  }
}

void WordAddressWriter::sync_control_without_tolerance(const MachineState& d) {
  if (d.control != MotionControlMode::Continuous || (d.tolerance == 0 && d.naive_tolerance == 0)) {
    sync_control_mode(d.control, 0, 0);
    return;
  }
  if (!options_.drop_path_tolerance) {
    cannot(concat({"a path blending tolerance (G64 P", format_number(d.tolerance, style_), ")"}),
           "its continuous mode has none (--drop-path-tolerance writes it without)");
  }
  if (!said_dropped_ && options_.comments != Comments::None) {
    write_comment_line(concat({"ncbridge: G64 P", format_number(d.tolerance, style_),
                               " (LinuxCNC's path tolerance) written as G64: the control blends by its own settings"}));
    said_dropped_ = true;
  }
  sync_control_mode(MotionControlMode::Continuous, 0, 0);
}

void WordAddressWriter::sync_overrides(const MachineState& d) {
  if (reader_.feed_override != d.feed_override && reader_.speed_override != d.speed_override &&
      d.feed_override == d.speed_override) {
    put(Slot::Override) += d.feed_override ? "M48" : "M49";
    if (d.feed_override) {
      reader_.apply(EnableFeedOverride{0});
      reader_.apply(EnableSpeedOverride{0});
    } else {
      reader_.apply(DisableFeedOverride{0});
      reader_.apply(DisableSpeedOverride{0});
    }
  }
  if (reader_.feed_override != d.feed_override) {
    put(Slot::Override) += d.feed_override ? "M50 P1" : "M50 P0";
    if (d.feed_override) reader_.apply(EnableFeedOverride{0}); else reader_.apply(DisableFeedOverride{0});
  }
  if (reader_.speed_override != d.speed_override) {
    put(Slot::Override) += d.speed_override ? "M51 P1" : "M51 P0";
    if (d.speed_override) reader_.apply(EnableSpeedOverride{0}); else reader_.apply(DisableSpeedOverride{0});
  }
  if (reader_.adaptive_feed != d.adaptive_feed) {
    put(Slot::Override) += d.adaptive_feed ? "M52 P1" : "M52 P0";
    if (d.adaptive_feed) reader_.apply(EnableAdaptiveFeed{}); else reader_.apply(DisableAdaptiveFeed{});
  }
  if (reader_.feed_hold != d.feed_hold) {
    put(Slot::Override) += d.feed_hold ? "M53 P1" : "M53 P0";
    if (d.feed_hold) reader_.apply(EnableFeedHold{}); else reader_.apply(DisableFeedHold{});
  }
}

// ---------------------------------------------------------------------------------------------
// actions

void WordAddressWriter::leave_cycles() {
  run_p_ = 0;
  if (!is_cycle_motion(cycle_.motion)) return;
  flush();
  put(Slot::Motion) += "G80";
  flush();
  note_other_motion(cycle_, 800);
}

void WordAddressWriter::motion_word(std::string& s, int motion) {
  if (cycle_.motion == motion && !incremental_) return;
  s += motion == 0 ? "G0" : motion == 10 ? "G1" : motion == 20 ? "G2" : "G3";
}

bool WordAddressWriter::axis_supported(char letter) const {
  (void)letter;
  return true;
}

void WordAddressWriter::axis_words(std::string& s, const Pose& end, bool always_one) {
  bool any = false;
  for (const AxisField& a : kAxes) {
    const double v = end.*a.field;
    const double now = reader_.position.*a.field;
    if (v == now) continue;
    if (!axis_supported(a.letter)) cannot(std::string("a move of the ") + a.letter + " axis");
    if (!s.empty() && s.back() != ' ') s.push_back(' ');
    if (a.linear) append(s, a.letter, incremental_ ? length(v - now) : v);
    else append_plain(s, a.letter, incremental_ ? rounded(v - now, 4) : v);
    any = true;
  }
  if (!any && always_one) {
    // a move that does not move: written anyway, as the source had it
    if (!s.empty() && s.back() != ' ') s.push_back(' ');
    append(s, 'Z', incremental_ ? 0.0 : reader_.position.z);
  }
}

void WordAddressWriter::traverse(const Pose& end) {
  leave_cycles();
  const Pose e = rounded_pose(end);
  std::string& s = put(Slot::Motion);
  motion_word(s, 0);
  axis_words(s, e, true);
  flush();
  reader_.apply(StraightTraverse{e});
  note_other_motion(cycle_, 0);
}

void WordAddressWriter::feed(const Pose& end) {
  leave_cycles();
  const Pose e = rounded_pose(end);
  std::string& s = put(Slot::Motion);
  motion_word(s, 10);
  axis_words(s, e, true);
  flush();
  reader_.apply(StraightFeed{e});
  note_other_motion(cycle_, 10);
}

void WordAddressWriter::write_turns(std::string& s, int turns) {
  s.push_back(' ');
  append_int(s, "P", turns);
}

void WordAddressWriter::arc(const ArcFeed& a) {
  leave_cycles();
  const Plane plane = reader_.plane;
  if (plane != Plane::XY && plane != Plane::XZ && plane != Plane::YZ) cannot("an arc in the UV, UW or VW plane");
  const PlaneLetters p = plane_letters(plane);
  const Pose start = reader_.position;
  const bool inch = reader_.units == Units::Inches;
  int decimals = length_decimals();
  Pose end;
  double c1 = 0, c2 = 0;
  // the end on the circle within the reader's tolerance: finer digits for a small arc if needed
  for (;; ++decimals) {
    end = arc_end(start, a, plane);
    for (const AxisField& f : kAxes) end.*f.field = f.linear ? rounded(end.*f.field, decimals) : rounded(end.*f.field, 4);
    c1 = start.*p.first + rounded(rounded(a.first_axis, decimals) - start.*p.first, decimals);
    c2 = start.*p.second + rounded(rounded(a.second_axis, decimals) - start.*p.second, decimals);
    if (arc_radius_ok(c1, c2, start.*p.first, start.*p.second, end.*p.first, end.*p.second, inch)) break;
    if (decimals >= length_decimals() + 3) cannot("an arc whose end is not on its circle");
  }
  // A path mode's P (G64 P..) waiting for this block would be read as the arc's turns.
  if (slot_text_[static_cast<int>(Slot::Control)].find('P') != std::string::npos) flush();
  std::string& s = put(Slot::Motion);
  const int motion = a.rotation < 0 ? 20 : 30;
  s += motion == 20 ? "G2" : "G3";
  NumberStyle fine = style_;
  fine.decimals = decimals;
  fine.point_always = point_always_;
  auto word = [&](char letter, double v) {
    s.push_back(' ');
    s.push_back(letter);
    append_number(s, v, fine);
  };
  for (const AxisField& f : kAxes) {
    const bool in_plane = f.field == p.first || f.field == p.second;
    const double v = end.*f.field, now = start.*f.field;
    if (!in_plane && v == now) continue;
    if (!axis_supported(f.letter)) cannot(std::string("an arc moving the ") + f.letter + " axis");
    if (f.linear) word(f.letter, incremental_ ? v - now : v);
    else {
      s.push_back(' ');
      append_plain(s, f.letter, incremental_ ? v - now : v);
    }
  }
  word(p.first_offset, c1 - start.*p.first);
  word(p.second_offset, c2 - start.*p.second);
  const int turns = a.rotation < 0 ? -a.rotation : a.rotation;
  if (turns > 1) write_turns(s, turns);
  flush();
  ArcFeed written = a;
  written.first_end = end.*p.first;
  written.second_end = end.*p.second;
  written.axis_end_point = end.*p.normal;
  written.first_axis = c1;
  written.second_axis = c2;
  written.a = end.a; written.b = end.b; written.c = end.c;
  written.u = end.u; written.v = end.v; written.w = end.w;
  reader_.apply(written);
  note_other_motion(cycle_, motion);
}

void WordAddressWriter::write_dwell(double seconds) {
  std::string& s = put(Slot::Dwell);
  s += "G4 ";
  append_plain(s, 'P', seconds);
}

void WordAddressWriter::dwell(double seconds) {
  leave_cycles();
  write_dwell(rounded(seconds, 4));
  flush();
  reader_.apply(Dwell{rounded(seconds, 4)});
}

void WordAddressWriter::write_tool_change(int tool) {
  if (tool != reader_.selected_tool) {
    append_int(put(Slot::Tool), "T", tool);
    reader_.apply(SelectTool{tool});
  }
  put(Slot::ToolChange) += "M6";
}

void WordAddressWriter::tool_change(int tool) {
  leave_cycles();
  write_tool_change(tool);
  flush();
  reader_.apply(StartChange{});
  reader_.apply(StopSpindleTurning{0});
  reader_.apply(ChangeTool{0});
}

void WordAddressWriter::action(const Call& call, const MachineState& desired) {
  leave_cycles();
  write_other_action(call, desired);
}

void WordAddressWriter::write_other_action(const Call& call, const MachineState& desired) {
  const Data& d = call.data;
  if (std::holds_alternative<ProgramStop>(d)) {
    put(Slot::Stop) += "M0";
  } else if (std::holds_alternative<OptionalProgramStop>(d)) {
    put(Slot::Stop) += "M1";
  } else if (std::holds_alternative<PalletShuttle>(d)) {
    put(Slot::Stop) += "M60";
    reader_.apply(PalletShuttle{});
    reader_.apply(ProgramStop{});
  } else if (const auto* o = std::get_if<OrientSpindle>(&d)) {
    std::string& s = put(Slot::Spindle);
    s += "M19 ";
    append_plain(s, 'R', o->orientation);
    append_int(s, " P", o->mode);
  } else if (const auto* w = std::get_if<WaitSpindleOrientComplete>(&d)) {
    std::string& s = put(Slot::Spindle);
    s += "M19 ";
    append_plain(s, 'Q', w->timeout);
  } else if (const auto* n = std::get_if<ChangeToolNumber>(&d)) {
    append_int(put(Slot::ToolChange), "M61 Q", n->number);
    reader_.apply(*n);
  } else if (const auto* e = std::get_if<SetToolTableEntry>(&d)) {
    if (e->pocket == 0 && last_entry_ && last_entry_->tool == e->tool) {
      // the reader's copy for the loaded tool, made by the G10 L1 just written
      last_entry_.reset();
      return;
    }
    if (e->pocket == 0) cannot("SET_TOOL_TABLE_ENTRY of the spindle alone (pocket 0)");
    flush();
    std::string& s = put(Slot::NonModal);
    append_int(s, "G10 L1 P", e->tool);
    for (const AxisField& a : kAxes) {
      // U V W only when set (LinuxCNC's rs274 is built for X Y Z A B C)
      if ((a.letter == 'U' || a.letter == 'V' || a.letter == 'W') && e->offset.*a.field == 0) continue;
      s.push_back(' ');
      if (a.linear) append(s, a.letter, e->offset.*a.field); else append_plain(s, a.letter, e->offset.*a.field);
    }
    s.push_back(' ');
    append(s, 'R', e->diameter / 2.0);
    s.push_back(' ');
    append_plain(s, 'I', e->frontangle);
    s.push_back(' ');
    append_plain(s, 'J', e->backangle);
    append_int(s, " Q", e->orientation);
    tool_offsets_mm_[e->tool] = to_mm(rounded_pose(e->offset), reader_.mm_per_unit());
    last_entry_ = *e;
  } else if (std::holds_alternative<StraightFeed>(d) && desired.synch) {
    // G33: spindle-synchronised motion
    std::string& s = put(Slot::Motion);
    s += "G33";
    const Pose end = rounded_pose(std::get<StraightFeed>(d).end);
    axis_words(s, end, true);
    s.push_back(' ');
    append(s, 'K', desired.synch_feed_per_revolution);
    reader_.apply(StartSpeedFeedSynch{0, length(desired.synch_feed_per_revolution), false});
    reader_.apply(StraightFeed{end});
    reader_.apply(StopSpeedFeedSynch{});
    note_other_motion(cycle_, 330);
  } else if (const auto* r = std::get_if<RigidTap>(&d)) {
    if (!desired.synch) cannot("RIGID_TAP without spindle synchronisation");
    std::string& s = put(Slot::Motion);
    s += "G33.1";
    const Pose end = rounded_pose(r->end);
    axis_words(s, end, true);
    s.push_back(' ');
    append(s, 'K', desired.synch_feed_per_revolution);
    reader_.apply(StartSpeedFeedSynch{0, length(desired.synch_feed_per_revolution), false});
    reader_.apply(RigidTap{end, r->scale});
    reader_.apply(StopSpeedFeedSynch{});
    note_other_motion(cycle_, 331);
  } else {
    cannot(std::string(name_of(d)));
  }
  flush();
}

// ---------------------------------------------------------------------------------------------
// canned cycles

bool WordAddressWriter::has_cycle(int motion) const {
  return motion == 730 || motion == 740 || motion == 810 || motion == 820 || motion == 830 || motion == 840 ||
         motion == 850 || motion == 860 || motion == 880 || motion == 890;
}

bool WordAddressWriter::reads_cycle_dwell(int motion) const {
  return motion == 820 || motion == 860 || motion == 880 || motion == 890 || motion == 740 || motion == 840;
}

void WordAddressWriter::append_cycle_dwell(std::string& s, double seconds) {
  s.push_back(' ');
  append_plain(s, 'P', seconds);
}

bool WordAddressWriter::cycle(const Hole& hole, const MachineState& desired) {
  const CycleTag& t = hole.tag;
  const int motion = t.g_code_x10;
  if (!has_cycle(motion) || incremental_) return false;
  const Plane plane = t.plane == 1 ? Plane::YZ : t.plane == 2 ? Plane::XZ : Plane::XY;
  if (reader_.plane != plane) return false;
  const bool pecks = motion == 730 || motion == 830;
  const bool dwells = motion == 820 || motion == 860 || motion == 880 || motion == 890 || motion == 740 || motion == 840;
  CycleBlock block;
  block.motion = motion;
  block.a = length(t.x);
  block.b = length(t.y);
  block.r = length(t.r);
  block.z = length(t.z);
  block.q = pecks ? length(t.q) : 0.0;
  const bool writes_p = dwells && reads_cycle_dwell(motion);
  block.p = writes_p ? rounded(t.p, 4) : dwells ? run_p_ : 0.0;
  if (pecks && block.q <= 0) return false;
  MachineState state = reader_;
  CycleReader c = cycle_;
  c.retract_to_r = t.retract_to_r;
  const CycleReader before = c;
  std::vector<Data> made = simulate_cycle(state, c, block);
  std::vector<Data> source;
  source.reserve(hole.calls.size());
  for (const Call& call : hole.calls) source.push_back(call.data);
  if (!same_motion(desired, source, reader_, made, reader_.units == Units::Inches ? 1e-5 : 1e-4)) return false;

  if (cycle_.retract_to_r != t.retract_to_r || !retract_written_) put(Slot::Retract) += t.retract_to_r ? "G99" : "G98";
  retract_written_ = true;
  std::string& s = put(Slot::Motion);
  const char la = plane == Plane::YZ ? 'Y' : plane == Plane::XZ ? 'Z' : 'X';
  const char lb = plane == Plane::YZ ? 'Z' : plane == Plane::XZ ? 'X' : 'Y';
  const char lc = plane == Plane::YZ ? 'X' : plane == Plane::XZ ? 'Y' : 'Z';
  const bool modal = before.motion == motion && cycle_.motion == motion && before.r == block.r && before.z == block.z &&
                     (!pecks || before.q == block.q) && (!dwells || before.p == block.p);
  if (!modal) {
    append_int(s, "G", motion / 10);
    s.push_back(' ');
  }
  append(s, la, block.a);
  s.push_back(' ');
  append(s, lb, block.b);
  if (!modal) {
    s.push_back(' ');
    append(s, lc, block.z);
    s.push_back(' ');
    append(s, 'R', block.r);
    if (pecks) {
      s.push_back(' ');
      append(s, 'Q', block.q);
    }
    if (writes_p) append_cycle_dwell(s, block.p);
  }
  flush();
  if (writes_p) run_p_ = block.p;
  reader_ = state;
  cycle_ = c;
  return true;
}

// ---------------------------------------------------------------------------------------------
// the repeat construct

void WordAddressWriter::write_repeat_begin(std::uint32_t count) {
  ++repeat_label_;
  line(concat({"o", number_text(100 + repeat_label_), " repeat [", number_text(count), "]"}));
  put(Slot::Distance) += "G91";
  flush();
}

void WordAddressWriter::write_repeat_end() {
  put(Slot::Distance) += "G90";
  flush();
  line(concat({"o", number_text(100 + repeat_label_), " endrepeat"}));
}

void WordAddressWriter::begin_repeat(std::uint32_t count, double z_shift) {
  leave_cycles();
  flush();
  repeat_start_ = reader_.position;
  repeat_count_ = count;
  repeat_shift_ = length(z_shift);
  write_repeat_begin(count);
  incremental_ = true;
  // the first move of every copy names its motion and feed: a copy starts where the last ended
  reader_.feed_mm = std::nan("");
  cycle_.motion = -1;
}

void WordAddressWriter::end_repeat() {
  flush();
  Pose expected = repeat_start_;
  expected.z = length(expected.z + repeat_shift_);
  if (!near(reader_.position, expected, 1e-9)) {
    cannot("a repeated body that does not end where it began, shifted by the Z step",
           "the copies would not join up");
  }
  incremental_ = false;
  write_repeat_end();
  reader_.position.z = length(repeat_start_.z + repeat_shift_ * repeat_count_);
}

}  // namespace ncbridge::gcode_writer
