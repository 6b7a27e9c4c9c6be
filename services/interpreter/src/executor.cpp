#include "executor.hpp"

#include <cmath>

#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter {

using namespace canonical;

Executor::Executor(const Options& options, Parameters& parameters, Sink& sink)
    : options_(options),
      params_(parameters),
      sink_(sink),
      tools_(options.tools),
      tool_table_given_(!options.tools.empty()),
      comp_out_(sink),
      comp_(comp_out_, [this](const Source& source) {
        return SourceLocation{file_ ? *file_ : std::string(), source.line, comp_column_};
      }) {}

Executor::~Executor() = default;

// Every error names a line and a column; where no word is to blame, the block's first column.
void Executor::fail(std::uint32_t column, const std::string& message) const {
  throw InputError({file_ ? *file_ : std::string(), line_ == 0 ? 1 : line_, column == 0 ? 1 : column}, message);
}

void Executor::warn(std::uint32_t column, const std::string& message) const {
  if (options_.strict) fail(column, message + " (refused under --strict)");
  if (options_.warning) options_.warning({file_ ? *file_ : std::string(), line_, column}, message);
}

void Executor::emit(Data data) {
  Call call{std::move(data), source_, cycle_tag_};
  if (comp_.active()) {
    comp_.other(call);
  } else {
    sink_.call(call);
  }
}

void Executor::CompPlaneSink::call(const Call& call) {
  if (xz) {
    if (const auto* feed = std::get_if<StraightFeed>(&call.data)) {
      out_.call(Call{StraightFeed{comp_to_xz(feed->end)}, call.source, call.cycle});
      return;
    }
    if (const auto* traverse = std::get_if<StraightTraverse>(&call.data)) {
      out_.call(Call{StraightTraverse{comp_to_xz(traverse->end)}, call.source, call.cycle});
      return;
    }
  }
  out_.call(call);
}

void Executor::end_of_file() {
  comp_.reset();
  s_.comp_side = Side::Off;
}

Pose Executor::to_units(const Pose& mm) const {
  double k = s_.mm_per_unit();
  return Pose{mm.x / k, mm.y / k, mm.z / k, mm.a, mm.b, mm.c, mm.u / k, mm.v / k, mm.w / k};
}

std::optional<double> Executor::computed(std::string_view name) const {
  const Pose& p = s_.position;
  if (name == "_x") return p.x;
  if (name == "_y") return p.y;
  if (name == "_z") return p.z;
  if (name == "_a") return p.a;
  if (name == "_b") return p.b;
  if (name == "_c") return p.c;
  if (name == "_u") return p.u;
  if (name == "_v") return p.v;
  if (name == "_w") return p.w;
  if (name == "_line") return static_cast<double>(source_.line);  // the block being read
  if (name == "_metric") return s_.units == Units::Millimeters ? 1.0 : 0.0;
  if (name == "_imperial") return s_.units == Units::Inches ? 1.0 : 0.0;
  if (name == "_absolute") return s_.distance == DistanceMode::Absolute ? 1.0 : 0.0;
  if (name == "_incremental") return s_.distance == DistanceMode::Incremental ? 1.0 : 0.0;
  if (name == "_feed") return s_.feed_rate;
  if (name == "_rpm") return s_.speed;
  if (name == "_current_tool") return static_cast<double>(s_.tool_in_spindle);
  if (name == "_selected_tool") return static_cast<double>(s_.selected_tool);
  if (name == "_motion_mode") return static_cast<double>(s_.motion);  // G code x10, as LinuxCNC
  if (name == "_coord_system") return 530.0 + 10.0 * s_.coord_system;
  if (name == "_task") return 0.0;
  // The rest of LinuxCNC's read-only modal parameters (LinuxCNC 2.9: _vmajor 2, _vminor 9).
  if (name == "_vmajor") return 2.9;
  if (name == "_vminor") return 0.0;
  if (name == "_plane") {
    switch (s_.plane) {
      case Plane::XY: return 170.0;
      case Plane::XZ: return 180.0;
      case Plane::YZ: return 190.0;
      case Plane::UV: return 171.0;
      case Plane::UW: return 181.0;
      case Plane::VW: return 191.0;
    }
  }
  if (name == "_ccomp") return s_.comp_side == Side::Left ? 410.0 : s_.comp_side == Side::Right ? 420.0 : 400.0;
  if (name == "_inverse_time") return s_.feed_mode == FeedMode::InverseTime ? 1.0 : 0.0;
  if (name == "_units_per_minute") return s_.feed_mode == FeedMode::UnitsPerMinute ? 1.0 : 0.0;
  if (name == "_units_per_rev") return s_.feed_mode == FeedMode::UnitsPerRevolution ? 1.0 : 0.0;
  if (name == "_tool_offset") return s_.tool_offset_mm == Pose{} ? 0.0 : 1.0;
  if (name == "_retract_r_plane") return s_.retract == RetractMode::RPlane ? 1.0 : 0.0;
  if (name == "_retract_old_z") return s_.retract == RetractMode::OldZ ? 1.0 : 0.0;
  if (name == "_spindle_rpm_mode") return s_.css ? 0.0 : 1.0;
  if (name == "_spindle_css_mode") return s_.css ? 1.0 : 0.0;
  if (name == "_ijk_absolute_mode") return s_.arc_distance == DistanceMode::Absolute ? 1.0 : 0.0;
  if (name == "_lathe_diameter_mode") return 0.0;
  if (name == "_lathe_radius_mode") return 1.0;
  if (name == "_spindle_on") return s_.spindle != Direction::Stopped ? 1.0 : 0.0;
  if (name == "_spindle_cw") return s_.spindle == Direction::Clockwise ? 1.0 : 0.0;
  if (name == "_mist") return s_.mist ? 1.0 : 0.0;
  if (name == "_flood") return s_.flood ? 1.0 : 0.0;
  if (name == "_speed_override") return s_.speed_override ? 1.0 : 0.0;
  if (name == "_feed_override") return s_.feed_override ? 1.0 : 0.0;
  if (name == "_adaptive_feed") return s_.adaptive_feed ? 1.0 : 0.0;
  if (name == "_feed_hold") return s_.feed_hold ? 1.0 : 0.0;
  return std::nullopt;
}

void Executor::start() {
  s_ = ModalState{};
  // coordinate systems and G92 from the parameters (all zero without a parameter file)
  write_parameters();
  write_tool_parameters();
  emit(UseLengthUnits{s_.units});
  emit_g5x();
  emit_g92();
  emit(SetXyRotation{s_.rotation()});
  emit(SetFeedReference{FeedReference::Xyz});
  emit(OnReset{});
}

// ---------------------------------------------------------------------------------------------
// One block, in the NIST order of execution (LinuxCNC execute_block / convert_m / convert_g).
bool Executor::execute(const BlockCommand& b, const Source& source, const std::string& file) {
  source_ = source;
  file_ = &file;
  line_ = b.line;
  cycle_tag_ = spelled_hole_;
  comp_column_ = b.g[kGMotion] != -1 ? b.g_column[kGMotion] : 1;
  check_block(b);

  // STEP 1: comment or message
  if (!b.comment.empty() || b.comment_is_message || b.comment_action != BlockCommand::CommentAction::Comment) {
    do_comment(b);
  }
  // STEP 2: spindle mode, feed mode, F, S, T
  if (b.g[kGSpindleMode] != -1) do_spindle_mode(b, b.g[kGSpindleMode]);
  if (b.g[kGFeedMode] != -1) do_feed_mode(b.g[kGFeedMode]);
  if (b.has('f') && s_.feed_mode != FeedMode::InverseTime) do_feed_rate(b);
  if (b.has('s')) do_speed(b);
  if (b.has('t')) do_tool_select(b);
  // STEP 3: M codes other than stops
  if (b.m[kMToolChange] != -1) do_tool_change(b);
  if (b.m[kMSpindle] != -1) do_spindle(b);
  if (b.m[kMCoolant] != -1) do_coolant(b);
  if (b.m[kMOverride] != -1) do_overrides(b);
  if (b.m[kMInput] != -1) do_wait_on_input(b);
  // STEP 4: G codes
  int g0 = b.g[kGNonModal];
  if (g0 == 40) do_dwell(b);
  if (b.g[kGPlane] != -1) do_plane(b, b.g[kGPlane]);
  if (b.g[kGUnits] != -1) do_units(b.g[kGUnits]);
  if (b.g[kGCutterComp] != -1) do_cutter_comp(b, b.g[kGCutterComp]);
  if (b.g[kGToolLength] != -1) do_tool_length_offset(b, b.g[kGToolLength]);
  if (b.g[kGCoordSystem] != -1) do_coordinate_system(b.g[kGCoordSystem], b.g_column[kGCoordSystem]);
  if (b.g[kGControl] != -1) do_control_mode(b, b.g[kGControl]);
  if (b.g[kGDistance] != -1) do_distance_mode(b.g[kGDistance]);
  if (b.g[kGArcDistance] != -1) do_distance_mode(b.g[kGArcDistance]);
  if (b.g[kGRetract] != -1) do_retract_mode(b.g[kGRetract]);
  switch (g0) {
    case 53: nurbs_end(b); break;
    case 100: do_g10(b); break;
    case 280: case 281: case 300: case 301: do_home(b, g0); break;
    case 520: case 920: case 921: case 922: case 923: do_axis_offsets(b, g0); break;
    default: break;
  }
  // motion: the block's motion code, or the modal one when axis words are present
  bool axis_motion = g0 != 100 && g0 != 280 && g0 != 300 && g0 != 520 && g0 != 920 && b.g[kGToolLength] != 431 &&
                     (b.has_axis() || b.has_polar());
  if (b.g[kGMotion] != -1) {
    do_motion(b, b.g[kGMotion], g0 == 530);
  } else if (axis_motion) {
    do_motion(b, s_.motion, g0 == 530);
  }
  // STEP 5: stops
  bool ended = b.m[kMStop] != -1 && do_stop(b);
  write_position_parameters();
  return ended;
}

// #5420-#5428: the current position in program coordinates.
void Executor::write_position_parameters() {
  const Pose& p = s_.position;
  const double values[9] = {p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w};
  for (int i = 0; i < 9; ++i) params_.set_numbered(5420 + i, values[i]);
}

void Executor::check_block(const BlockCommand& b) {
  int g0 = b.g[kGNonModal];
  int motion = b.g[kGMotion];
  bool g0_uses_axes = g0 == 100 || g0 == 280 || g0 == 300 || g0 == 520 || g0 == 920 || b.g[kGToolLength] == 431;
  if (b.has_polar()) {  // LinuxCNC enhance_block
    if (s_.plane != Plane::XY) fail(b.polar_column(), "Cannot use polar coordinate except in G17 plane");
    if (b.has('x')) fail(b.col('x'), "Cannot specify both polar coordinate and X word");
    if (b.has('y')) fail(b.col('y'), "Cannot specify both polar coordinate and Y word");
    if (g0_uses_axes && (motion == -1 || motion == 800)) {
      fail(b.polar_column(), "Polar coordinates can only be used for motion");
    }
  }
  const bool axes = b.has_axis() || b.has_polar();
  if (g0_uses_axes && motion != -1 && motion != 800 && axes) {
    fail(b.g_column[kGMotion], "Cannot use two G codes that both use axis values");
  }
  if (motion == 800 && axes && !g0_uses_axes) {
    fail(b.g_column[kGMotion], "Cannot use axis values with g80");
  }
  if (g0 == 53 && motion != 52 && motion != -1) {
    fail(b.g_column[kGNonModal], "Between G5.2 and G5.3 codes, only additional G5.2 codes are allowed.");
  }
  if (motion == -1 && axes && !g0_uses_axes && (s_.motion == 800 || s_.motion == -1)) {
    fail(b.has_polar() ? b.polar_column() : 0, "Cannot use axis values without a g code that uses them");
  }
  if (g0 == 530 && motion != 0 && motion != 10 && !(motion == -1 && (s_.motion == 0 || s_.motion == 10))) {
    fail(b.g_column[kGNonModal], "Must use G0 or G1 with G53");
  }
  if (b.has('p') && b.g[kGNonModal] != 40 && b.g[kGNonModal] != 100 && b.g[kGControl] != 640 &&
      motion != 740 && motion != 820 && motion != 840 && motion != 860 && motion != 880 && motion != 890 &&
      motion != 20 && motion != 30 && motion != 50 && motion != 52 && b.m[kMOverride] == -1 && b.m[kMSpindle] != 19 &&
      b.m[kMInput] != 66 &&
      !(motion == -1 && (s_.motion == 20 || s_.motion == 30 || s_.motion == 52 || s_.motion == 740 || s_.motion == 820 ||
                         s_.motion == 840 || s_.motion == 860 || s_.motion == 880 || s_.motion == 890))) {
    fail(b.col('p'), "P word with no G code or M code that uses it");
  }
  if (b.has('e') && b.m[kMInput] != 66) fail(b.col('e'), "E word with no G70, G76, M66, M67 or M68 to use it");
  if (g0 == 40 && !b.has('p')) fail(b.g_column[kGNonModal], "Dwell time P word missing with G4");
}

void Executor::do_comment(const BlockCommand& b) {
  if (b.comment_is_message) {
    emit(Message{std::string(b.comment)});
    return;
  }
  using Action = BlockCommand::CommentAction;
  switch (b.comment_action) {
    case Action::Comment: break;
    case Action::Print: emit(Print{std::string(b.comment)}); return;
    case Action::Log: emit(Log{std::string(b.comment)}); return;
    case Action::LogOpen: emit(LogOpen{std::string(b.comment)}); return;
    case Action::LogAppend: emit(LogAppend{std::string(b.comment)}); return;
    case Action::LogClose: emit(LogClose{}); return;
    case Action::Nothing: return;
  }
  std::string_view text = b.comment;
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  emit(Comment{std::string(text)});
}

void Executor::do_feed_mode(int g) {
  if (g == 930) {
    emit(Comment{"interpreter: feed mode set to inverse time"});
    emit(SetFeedMode{0, 0});
    s_.feed_mode = FeedMode::InverseTime;
  } else if (g == 940) {
    emit(Comment{"interpreter: feed mode set to units per minute"});
    emit(SetFeedMode{0, 0});
    s_.feed_mode = FeedMode::UnitsPerMinute;
    s_.feed_rate = 0;
    emit(SetFeedRate{0});
  } else {
    emit(Comment{"interpreter: feed mode set to units per revolution"});
    emit(SetFeedMode{0, 1});
    s_.feed_mode = FeedMode::UnitsPerRevolution;
    s_.feed_rate = 0;
    emit(SetFeedRate{0});
  }
}

void Executor::do_feed_rate(const BlockCommand& b) {
  if (b.get('f') < 0) fail(b.col('f'), "Negative f word used");
  s_.feed_rate = b.get('f');
  emit(SetFeedRate{s_.feed_rate});
}

void Executor::do_speed(const BlockCommand& b) {
  double s = b.get('s');
  if (s < 0) fail(b.col('s'), "Negative spindle speed used");
  s_.speed = s;
  emit(SetSpindleSpeed{0, s});
}

void Executor::do_dwell(const BlockCommand& b) {
  double p = b.get('p');
  if (p < 0) fail(b.col('p'), "Negative dwell time");
  emit(Dwell{p});
}

void Executor::do_plane(const BlockCommand& b, int g) {
  Plane p = g == 170 ? Plane::XY : g == 180 ? Plane::XZ : g == 190 ? Plane::YZ
          : g == 171 ? Plane::UV : g == 181 ? Plane::UW : Plane::VW;
  if (s_.comp_side != Side::Off && p != s_.plane) {
    fail(b.g_column[kGPlane], "Cannot change planes with cutter radius compensation on");
  }
  s_.plane = p;
  emit(SelectPlane{p});
}

void Executor::do_units(int g) {
  Units u = g == 200 ? Units::Inches : Units::Millimeters;
  if (u != s_.units) {
    double k = (u == Units::Millimeters) ? 25.4 : 1.0 / 25.4;
    Pose& p = s_.position;
    p.x *= k; p.y *= k; p.z *= k; p.u *= k; p.v *= k; p.w *= k;
    if (s_.feed_rate != 0) s_.feed_rate *= k;  // LinuxCNC keeps the feed in the new units
    s_.cycle_r *= k;
    s_.cycle_z *= k;
    s_.cycle_initial_level *= k;
    s_.units = u;
  }
  emit(UseLengthUnits{u});
}

void Executor::do_control_mode(const BlockCommand& b, int g) {
  if (s_.comp_side != Side::Off) {
    fail(b.g_column[kGControl], "Cannot change control mode with cutter radius compensation on");
  }
  if (g == 610) {
    s_.control = MotionControlMode::ExactPath;
    emit(SetMotionControlMode{MotionControlMode::ExactPath, 0});
  } else if (g == 611) {
    s_.control = MotionControlMode::ExactStop;
    emit(SetMotionControlMode{MotionControlMode::ExactStop, 0});
  } else {
    double p = b.has('p') ? b.get('p') : 0.0;
    double q = b.has('q') ? b.get('q') : p;
    if (p < 0) fail(b.col('p'), "G64 P value must be non-negative");
    s_.control = MotionControlMode::Continuous;
    s_.control_tolerance = p;
    s_.naivecam_tolerance = q;
    emit(SetMotionControlMode{MotionControlMode::Continuous, p});
    emit(SetNaivecamTolerance{q});
  }
}

void Executor::do_distance_mode(int g) {
  switch (g) {
    case 900:
      if (s_.distance == DistanceMode::Incremental) emit(Comment{"interpreter: distance mode changed to absolute"});
      s_.distance = DistanceMode::Absolute;
      break;
    case 910:
      if (s_.distance == DistanceMode::Absolute) emit(Comment{"interpreter: distance mode changed to incremental"});
      s_.distance = DistanceMode::Incremental;
      break;
    case 901:
      if (s_.arc_distance == DistanceMode::Incremental) emit(Comment{"interpreter: IJK distance mode changed to absolute"});
      s_.arc_distance = DistanceMode::Absolute;
      break;
    case 911:
      if (s_.arc_distance == DistanceMode::Absolute) emit(Comment{"interpreter: IJK distance mode changed to incremental"});
      s_.arc_distance = DistanceMode::Incremental;
      break;
    default: break;
  }
}

void Executor::do_retract_mode(int g) {
  if (g == 980) {
    emit(Comment{"interpreter: retract mode set to old_z"});
    s_.retract = RetractMode::OldZ;
  } else {
    emit(Comment{"interpreter: retract mode set to r_plane"});
    s_.retract = RetractMode::RPlane;
  }
}

void Executor::do_overrides(const BlockCommand& b) {
  int m = b.m[kMOverride];
  bool on_p = !b.has('p') || b.get('p') != 0.0;
  switch (m) {
    case 48:
      emit(EnableFeedOverride{0});
      emit(EnableSpeedOverride{0});
      s_.feed_override = s_.speed_override = true;
      break;
    case 49:
      emit(DisableFeedOverride{0});
      emit(DisableSpeedOverride{0});
      s_.feed_override = s_.speed_override = false;
      break;
    case 50:
      if (on_p) emit(EnableFeedOverride{0}); else emit(DisableFeedOverride{0});
      s_.feed_override = on_p;
      break;
    case 51:
      if (on_p) emit(EnableSpeedOverride{0}); else emit(DisableSpeedOverride{0});
      s_.speed_override = on_p;
      break;
    case 52:
      if (on_p) emit(EnableAdaptiveFeed{}); else emit(DisableAdaptiveFeed{});
      s_.adaptive_feed = on_p;
      break;
    case 53:
      if (on_p) emit(EnableFeedHold{}); else emit(DisableFeedHold{});
      s_.feed_hold = on_p;
      break;
    default: break;
  }
}

// M66: wait on a digital (P) or analog (E) input. No canonical call: the machine waits. Without a
// machine, the input reads as rs274's simulation has it: a digital input as #5399 was (0 or 1),
// an analog one as #5399 unchanged.
void Executor::do_wait_on_input(const BlockCommand& b) {
  const std::uint32_t col = b.m_column[kMInput];
  const bool digital = b.has('p'), analog = b.has('e');
  const int wait_type = b.has('l') ? nearest_int(b.get('l')) : 0;
  const double timeout = b.has('q') ? b.get('q') : -1.0;
  if (digital && analog) fail(col, "Invalid to select both a digital and an analog input with M66");
  if (timeout <= 0 && b.has('l') && wait_type > 0) fail(col, "Zero timeout with wait type != immediate return");
  if (analog && b.has('l') && wait_type != 0) fail(col, "Can't select analog input with wait type != immediate return");
  if ((digital && nearest_int(b.get('p')) < 0) || (analog && nearest_int(b.get('e')) < 0) || (!digital && !analog)) {
    fail(col, "Need to have either a valid P or a valid E word with M66");
  }
  if (s_.comp_side != Side::Off) {
    fail(col, digital ? "Cannot wait for digital input with cutter radius compensation on"
                      : "Cannot wait for analog input with cutter radius compensation on");
  }
  if (digital) params_.set_numbered(5399, params_.numbered(5399) != 0.0 ? 1.0 : 0.0);
}

void Executor::do_coolant(const BlockCommand& b) {
  int m = b.m[kMCoolant];
  if (m == 7) {
    emit(MistOn{});
    s_.mist = true;
  } else if (m == 8) {
    emit(FloodOn{});
    s_.flood = true;
  } else {
    emit(MistOff{});
    emit(FloodOff{});
    s_.mist = s_.flood = false;
  }
}

// G40, G41/G42 (radius from the tool table: the D word's tool, else the tool in the spindle),
// G41.1/G42.1 (D is the diameter itself). LinuxCNC convert_cutter_compensation_on/off.
void Executor::do_cutter_comp(const BlockCommand& b, int g) {
  if (g == 400) {
    const bool was_active = comp_.active();
    const bool moved = was_active && comp_.radius() > 0.0 && comp_moved_;
    comp_.stop(source_);
    if (was_active) s_.position = from_comp(comp_.programmed_position());
    if (moved) arc_not_allowed_ = true;
    s_.comp_side = Side::Off;
    s_.comp_radius = 0;
    comp_moved_ = false;
    return;
  }
  const std::uint32_t col = b.g_column[kGCutterComp];
  if (s_.plane != Plane::XY && s_.plane != Plane::XZ) {
    fail(col, "Cutter radius compensation allowed only in XY, XZ planes");
  }
  if (s_.comp_side != Side::Off) fail(col, "Cannot turn cutter radius comp on when on");
  const double radius = comp_radius_of_tool(b, g);
  const Side side = (g == 410 || g == 411) ? Side::Left : Side::Right;
  comp_out_.xz = s_.plane == Plane::XZ;
  comp_.set_length_units(s_.units);
  comp_.set_position(to_comp(s_.position));
  comp_.start(side, radius, source_);
  s_.comp_side = comp_.side();
  s_.comp_radius = comp_.radius();
  comp_moved_ = false;
}

// The compensation radius in program units; negative when the tool table gives a negative
// diameter (the compensator then swaps the side, as LinuxCNC does).
double Executor::comp_radius_of_tool(const BlockCommand& b, int g) {
  const std::uint32_t col = b.g_column[kGCutterComp];
  const std::string code = g == 410 || g == 411 ? "G41" : "G42";
  if (g == 411 || g == 421) {
    if (!b.has('d')) fail(col, code + ".1 with no D word");
    return b.get('d') / 2.0;
  }
  const ToolEntry* t = &spindle_tool_;
  if (b.has('d')) {
    int tool = 0;
    const double d = b.get('d');
    tool = nearest_int(d);
    if (std::fabs(tool - d) >= 0.0001) fail(b.col('d'), code + " requires D word to be a whole number");
    if (tool < 0) fail(b.col('d'), "Negative D word tool radius index used");
    if (tool != 0 && tools_.find(tool) == nullptr) {
      fail(b.col('d'), "Requested tool " + std::to_string(tool) + " not found in the tool table");
    }
    t = tool_entry(tool);
  }
  return t == nullptr ? 0.0 : t->diameter_mm / s_.mm_per_unit() / 2.0;
}

}  // namespace ncbridge::interpreter
