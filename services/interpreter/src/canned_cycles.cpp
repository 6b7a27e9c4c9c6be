// Canned cycles G73, G74, G81-G89 in the XY, YZ and XZ planes (LinuxCNC convert_cycle*), with
// G98/G99 retract, L repeats, incremental positioning and Q pecks. Every call a cycle makes
// carries a CycleTag describing the hole.
#include <cmath>

#include "executor.hpp"

namespace ncbridge::interpreter {

using namespace canonical;

namespace {
constexpr double kPeckRapidDeltaInch = 0.010;  // LinuxCNC G83_RAPID_DELTA
constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
}

void Executor::canned_cycle(const BlockCommand& b, int motion) {
  const std::uint32_t col = b.g_column[kGMotion] ? b.g_column[kGMotion] : 1;
  if (s_.feed_rate == 0.0) fail(col, "Cannot feed with zero feed rate");
  if (s_.feed_mode == FeedMode::InverseTime) fail(col, "Cannot use inverse time feed with canned cycles");
  if (s_.comp_side != Side::Off) fail(col, "Cannot use canned cycles with cutter compensation on");
  if (s_.plane != Plane::XY && s_.plane != Plane::YZ && s_.plane != Plane::XZ) {
    fail(col, "Canned cycles are only supported in the XY, YZ and XZ planes");
  }
  bool same_cycle = s_.motion == motion;
  double r_word;
  if (b.has('r')) {
    r_word = b.get('r');
  } else if (same_cycle) {
    r_word = s_.cycle_r;
  } else {
    fail(col, "R clearance plane unspecified in cycle");
  }
  int repeats = 1;
  if (b.has('l')) {
    double l = b.get('l');
    if (l > static_cast<double>(options_.max_loop_iterations)) {
      fail(b.col('l'), "L word asks for more repeats than the iteration limit (" +
                           std::to_string(options_.max_loop_iterations) + ")");
    }
    repeats = static_cast<int>(std::lround(l));
    if (repeats == 0) fail(b.col('l'), "Cannot do zero repeats of cycle");
    if (repeats < 0) fail(b.col('l'), "Negative L word used");
  }
  for (char letter : {'u', 'v', 'w'}) {
    if (b.has(letter)) fail(b.col(letter), std::string("Cannot put a ") + static_cast<char>(letter - 32) + " in a canned cycle");
  }

  // The plane's axes: aa, bb in the plane, cc along its normal.
  double Pose::*fa = &Pose::x;
  double Pose::*fb = &Pose::y;
  double Pose::*fc = &Pose::z;
  char la = 'x', lb = 'y', lc = 'z';
  std::uint8_t plane_index = 0;
  if (s_.plane == Plane::YZ) {
    fa = &Pose::y; fb = &Pose::z; fc = &Pose::x; la = 'y'; lb = 'z'; lc = 'x'; plane_index = 1;
  } else if (s_.plane == Plane::XZ) {
    fa = &Pose::z; fb = &Pose::x; fc = &Pose::y; la = 'z'; lb = 'x'; lc = 'y'; plane_index = 2;
  }
  if (!same_cycle && !b.has(lc)) {
    fail(col, std::string(1, static_cast<char>(lc - 32)) + " value unspecified in " +
                  (plane_index == 0 ? "XY" : plane_index == 1 ? "YZ" : "XZ") + " plane canned cycle");
  }
  double cc_word = b.has(lc) ? b.get(lc) : s_.cycle_z;

  double current_cc = s_.position.*fc;
  double old_cc;
  if (s_.cycle_initial_level_valid) {
    old_cc = s_.cycle_initial_level;
  } else {
    old_cc = s_.cycle_initial_level = current_cc;
    s_.cycle_initial_level_valid = true;
  }
  double aa, bb, aa_inc = 0, bb_inc = 0, r, cc;
  // Polar coordinates (XY plane only): in G90 the hole position, in G91 a radius and an angle
  // added before each repeat (LinuxCNC convert_cycle_xy, CYCLE_MACRO).
  double radius_inc = 0, angle_inc = 0;
  if (s_.distance == DistanceMode::Absolute) {
    r = r_word;
    cc = cc_word;
    if (b.has_polar()) {
      const double radius = b.has_polar_radius ? b.polar_radius : std::hypot(s_.position.y, s_.position.x);
      const double theta = b.has_polar_angle ? b.polar_angle * kRadiansPerDegree : std::atan2(s_.position.y, s_.position.x);
      aa = radius * std::cos(theta);
      bb = radius * std::sin(theta);
    } else {
      aa = b.has(la) ? b.get(la) : s_.position.*fa;
      bb = b.has(lb) ? b.get(lb) : s_.position.*fb;
    }
  } else {
    if (b.has(la)) aa_inc = b.get(la);
    if (b.has(lb)) bb_inc = b.get(lb);
    if (b.has_polar_radius) radius_inc = b.polar_radius;
    if (b.has_polar_angle) angle_inc = b.polar_angle * kRadiansPerDegree;
    r = r_word + old_cc;
    cc = r + cc_word;
    aa = s_.position.*fa;
    bb = s_.position.*fb;
  }
  if (r < cc) {
    fail(col, std::string("R less than ") + static_cast<char>(lc - 32) + " in cycle in " +
                  (plane_index == 0 ? "XY" : plane_index == 1 ? "YZ" : "XZ") + " plane");
  }

  // Sticky cycle parameters, checked as LinuxCNC does.
  double p = 0, q = 0;
  bool needs_p = motion == 820 || motion == 860 || motion == 880 || motion == 890;
  const bool tapping = motion == 740 || motion == 840;
  if (needs_p || tapping) {
    if (!b.has('p') && !same_cycle && needs_p) {
      fail(col, "Dwell time P word missing with G" + std::to_string(motion / 10));
    }
    p = b.has('p') ? b.get('p') : s_.cycle_p;
  }
  if (motion == 730 || motion == 830) {
    if (!b.has('q') && !same_cycle) fail(col, "Q word missing with G" + std::to_string(motion / 10));
    q = b.has('q') ? b.get('q') : s_.cycle_q;
    if (q <= 0) fail(b.has('q') ? b.col('q') : col, "Negative or zero Q value used");
  }
  double i = 0, j = 0, k = 0;
  if (motion == 870) {
    if (!same_cycle) {
      if (!b.has('i')) fail(col, "I word missing with G87");
      if (!b.has('j')) fail(col, "J word missing with G87");
      if (!b.has('k')) fail(col, "K word missing with G87");
    }
    i = b.has('i') ? b.get('i') : s_.cycle_i;
    j = b.has('j') ? b.get('j') : s_.cycle_j;
    k = b.has('k') ? b.get('k') : s_.cycle_k;
    s_.cycle_i = i;
    s_.cycle_j = j;
    s_.cycle_k = k;
    if (s_.distance == DistanceMode::Incremental) k = cc + k;
  }
  if ((motion == 860 || motion == 870 || motion == 880) && s_.spindle == Direction::Stopped) {
    fail(col, "Spindle not turning in G" + std::to_string(motion / 10));
  }
  if (motion == 840 && s_.spindle != Direction::Clockwise) {
    fail(col, s_.spindle == Direction::Stopped ? "Spindle not turning in G84" : "Spindle turning counterclockwise in G84");
  }
  if (motion == 740 && s_.spindle != Direction::Counterclockwise) {
    fail(col, s_.spindle == Direction::Stopped ? "Spindle not turning in G74" : "Spindle turning clockwise in G74");
  }

  CycleTag tag;
  tag.g_code_x10 = static_cast<std::uint16_t>(motion);
  tag.retract_to_r = s_.retract == RetractMode::RPlane;
  tag.plane = plane_index;
  tag.r = r;
  tag.z = cc;
  tag.q = q;
  tag.p = p;
  tag.k = k;
  tag.repeat = static_cast<std::uint32_t>(repeats);
  // G91 polar steps: each hole is the last one turned by the angle and pushed out by the radius.
  auto turn_polar = [&](double& a, double& bv) {
    if (radius_inc != 0) {
      if (a == 0 && bv == 0) {
        fail(b.polar_radius_column, "Incremental motion with polar coordinates is indeterminate when at the origin");
      }
      const double theta = std::atan2(bv, a);
      const double radius = std::hypot(bv, a) + radius_inc;
      a = radius * std::cos(theta);
      bv = radius * std::sin(theta);
    }
    if (angle_inc != 0) {
      if (a == 0 && bv == 0) {
        fail(b.polar_angle_column, "Incremental motion with polar coordinates is indeterminate when at the origin");
      }
      const double theta = std::atan2(bv, a) + angle_inc;
      const double radius = std::hypot(bv, a);
      a = radius * std::cos(theta);
      bv = radius * std::sin(theta);
    }
  };
  tag.x = aa + aa_inc;
  tag.y = bb + bb_inc;
  turn_polar(tag.x, tag.y);
  tag.cycle_id = s_.cycle_count + 1;

  auto at = [&](double a, double bv, double c) {
    Pose pos = s_.position;
    pos.*fa = a;
    pos.*fb = bv;
    pos.*fc = c;
    return pos;
  };
  auto traverse = [&](double a, double bv, double c) { straight(false, at(a, bv, c), nullptr); };
  auto feed = [&](double a, double bv, double c) { straight(true, at(a, bv, c), nullptr); };

  cycle_tag_ = tag;
  if (old_cc < r) {
    traverse(s_.position.*fa, s_.position.*fb, r);
    old_cc = r;
    current_cc = old_cc;
  }
  double clear_cc = s_.retract == RetractMode::RPlane ? r : old_cc;
  tag.clearance = clear_cc;
  cycle_tag_ = tag;

  MotionControlMode save_mode = s_.control;
  if (save_mode != MotionControlMode::ExactPath) emit(SetMotionControlMode{MotionControlMode::ExactPath, 0});

  double rapid_delta = s_.units == Units::Millimeters ? kPeckRapidDeltaInch * 25.4 : kPeckRapidDeltaInch;
  for (int repeat = repeats; repeat > 0; --repeat) {
    aa += aa_inc;
    bb += bb_inc;
    turn_polar(aa, bb);
    tag.cycle_id = ++s_.cycle_count;
    tag.x = aa;
    tag.y = bb;
    cycle_tag_ = tag;
    if (repeat == repeats && current_cc > r) {
      traverse(aa, bb, current_cc);
      traverse(aa, bb, r);
    } else {
      traverse(aa, bb, clear_cc);
      if (clear_cc > r) traverse(aa, bb, r);
    }
    switch (motion) {
      case 810:
        feed(aa, bb, cc);
        traverse(aa, bb, clear_cc);
        break;
      case 820:
        feed(aa, bb, cc);
        emit(Dwell{p});
        traverse(aa, bb, clear_cc);
        break;
      case 730:
      case 830: {
        if ((r - cc) / q * repeats > static_cast<double>(options_.max_loop_iterations)) {
          fail(b.has('q') ? b.col('q') : col, "Q too small: more pecks than the iteration limit (" +
                                                  std::to_string(options_.max_loop_iterations) + ")");
        }
        for (double depth = r - q; depth > cc; depth -= q) {
          feed(aa, bb, depth);
          if (motion == 830) traverse(aa, bb, r);
          traverse(aa, bb, depth + rapid_delta);
        }
        feed(aa, bb, cc);
        traverse(aa, bb, clear_cc);
        break;
      }
      case 740:
      case 840: {
        // right-hand (G84) or left-hand (G74) tapping: the spindle reverses at the bottom
        const bool right_hand = motion == 840;
        bool feed_override = s_.feed_override, speed_override = s_.speed_override;
        emit(DisableFeedOverride{0});
        emit(DisableSpeedOverride{0});
        feed(aa, bb, cc);
        emit(StopSpindleTurning{0});
        if (right_hand) emit(StartSpindleCounterclockwise{0}); else emit(StartSpindleClockwise{0});
        emit(Dwell{p});
        feed(aa, bb, clear_cc);
        emit(StopSpindleTurning{0});
        if (right_hand) emit(StartSpindleClockwise{0}); else emit(StartSpindleCounterclockwise{0});
        if (feed_override) emit(EnableFeedOverride{0});
        if (speed_override) emit(EnableSpeedOverride{0});
        break;
      }
      case 850:
        feed(aa, bb, cc);
        feed(aa, bb, r);
        traverse(aa, bb, clear_cc);
        break;
      case 860:
        feed(aa, bb, cc);
        emit(Dwell{p});
        emit(StopSpindleTurning{0});
        traverse(aa, bb, clear_cc);
        if (s_.spindle == Direction::Clockwise) emit(StartSpindleClockwise{0}); else emit(StartSpindleCounterclockwise{0});
        break;
      case 870: {
        int dir = s_.spindle == Direction::Clockwise ? 2 : 3;  // CANON_DIRECTION values
        traverse(aa + i, bb + j, r);
        emit(StopSpindleTurning{0});
        emit(OrientSpindle{0, 0.0, dir});
        traverse(aa + i, bb + j, cc);
        traverse(aa, bb, cc);
        if (dir == 2) emit(StartSpindleClockwise{0}); else emit(StartSpindleCounterclockwise{0});
        feed(aa, bb, k);
        feed(aa, bb, cc);
        emit(StopSpindleTurning{0});
        emit(OrientSpindle{0, 0.0, dir});
        traverse(aa + i, bb + j, cc);
        traverse(aa + i, bb + j, clear_cc);
        traverse(aa, bb, clear_cc);
        if (dir == 2) emit(StartSpindleClockwise{0}); else emit(StartSpindleCounterclockwise{0});
        break;
      }
      case 880:
        feed(aa, bb, cc);
        emit(Dwell{p});
        emit(StopSpindleTurning{0});
        emit(ProgramStop{});
        if (s_.spindle == Direction::Clockwise) emit(StartSpindleClockwise{0}); else emit(StartSpindleCounterclockwise{0});
        break;
      case 890:
        feed(aa, bb, cc);
        emit(Dwell{p});
        feed(aa, bb, clear_cc);
        break;
      default:
        break;
    }
  }
  Pose final_pos = s_.position;
  final_pos.*fa = aa;
  final_pos.*fb = bb;
  final_pos.*fc = clear_cc;
  s_.position = final_pos;
  s_.cycle_z = cc_word;
  if (save_mode != MotionControlMode::ExactPath) {
    emit(SetMotionControlMode{save_mode, s_.control_tolerance});
    if (save_mode == MotionControlMode::Continuous) emit(SetNaivecamTolerance{s_.naivecam_tolerance});
  }
  cycle_tag_.reset();
  if (needs_p || tapping) s_.cycle_p = p;
  if (motion == 730 || motion == 830) s_.cycle_q = q;
  s_.cycle_l = repeats;
  s_.cycle_r = r_word;
  s_.motion = motion;
}

}  // namespace ncbridge::interpreter
