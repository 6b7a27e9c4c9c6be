#include "cycle_motion.hpp"

namespace ncbridge::gcode_writer {

using namespace canonical;

std::vector<Data> simulate_cycle(MachineState& s, CycleReader& cycle, const CycleBlock& block) {
  std::vector<Data> out;
  auto emit = [&](Data d) {
    s.apply(d);
    out.push_back(std::move(d));
  };
  double Pose::*fa = &Pose::x;
  double Pose::*fb = &Pose::y;
  double Pose::*fc = &Pose::z;
  if (s.plane == Plane::YZ) {
    fa = &Pose::y; fb = &Pose::z; fc = &Pose::x;
  } else if (s.plane == Plane::XZ) {
    fa = &Pose::z; fb = &Pose::x; fc = &Pose::y;
  }
  const int motion = block.motion;
  auto at = [&](double a, double b, double c) {
    Pose p = s.position;
    p.*fa = a;
    p.*fb = b;
    p.*fc = c;
    return p;
  };
  auto traverse = [&](double a, double b, double c) { emit(StraightTraverse{at(a, b, c)}); };
  auto feed = [&](double a, double b, double c) { emit(StraightFeed{at(a, b, c)}); };

  double current_cc = s.position.*fc;
  double old_cc;
  if (cycle.initial_valid) {
    old_cc = cycle.initial_level;
  } else {
    old_cc = cycle.initial_level = current_cc;
    cycle.initial_valid = true;
  }
  const double aa = block.a, bb = block.b, r = block.r, cc = block.z;
  if (old_cc < r) {
    traverse(s.position.*fa, s.position.*fb, r);
    old_cc = r;
    current_cc = old_cc;
  }
  const double clear_cc = cycle.retract_to_r ? r : old_cc;
  const MotionControlMode save_mode = s.control;
  const double save_tolerance = s.tolerance, save_naive = s.naive_tolerance;
  if (save_mode != MotionControlMode::ExactPath) emit(SetMotionControlMode{MotionControlMode::ExactPath, 0});
  const double rapid_delta = s.units == Units::Millimeters ? 0.010 * 25.4 : 0.010;
  if (current_cc > r) {
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
      emit(Dwell{block.p});
      traverse(aa, bb, clear_cc);
      break;
    case 730:
    case 830:
      for (double depth = r - block.q; depth > cc; depth -= block.q) {
        feed(aa, bb, depth);
        if (motion == 830) traverse(aa, bb, r);
        traverse(aa, bb, depth + rapid_delta);
      }
      feed(aa, bb, cc);
      traverse(aa, bb, clear_cc);
      break;
    case 740:
    case 840: {
      const bool right_hand = motion == 840;
      const bool feed_override = s.feed_override, speed_override = s.speed_override;
      emit(DisableFeedOverride{0});
      emit(DisableSpeedOverride{0});
      feed(aa, bb, cc);
      emit(StopSpindleTurning{0});
      if (right_hand) emit(StartSpindleCounterclockwise{0}); else emit(StartSpindleClockwise{0});
      emit(Dwell{block.p});
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
    case 860: {
      const Direction direction = s.spindle;
      feed(aa, bb, cc);
      emit(Dwell{block.p});
      emit(StopSpindleTurning{0});
      traverse(aa, bb, clear_cc);
      if (direction == Direction::Clockwise) emit(StartSpindleClockwise{0}); else emit(StartSpindleCounterclockwise{0});
      break;
    }
    case 870: {
      const int dir = s.spindle == Direction::Clockwise ? 2 : 3;
      traverse(aa + block.i, bb + block.j, r);
      emit(StopSpindleTurning{0});
      emit(OrientSpindle{0, 0.0, dir});
      traverse(aa + block.i, bb + block.j, cc);
      traverse(aa, bb, cc);
      if (dir == 2) emit(StartSpindleClockwise{0}); else emit(StartSpindleCounterclockwise{0});
      feed(aa, bb, block.k);
      feed(aa, bb, cc);
      emit(StopSpindleTurning{0});
      emit(OrientSpindle{0, 0.0, dir});
      traverse(aa + block.i, bb + block.j, cc);
      traverse(aa + block.i, bb + block.j, clear_cc);
      traverse(aa, bb, clear_cc);
      if (dir == 2) emit(StartSpindleClockwise{0}); else emit(StartSpindleCounterclockwise{0});
      break;
    }
    case 880: {
      const Direction direction = s.spindle;
      feed(aa, bb, cc);
      emit(Dwell{block.p});
      emit(StopSpindleTurning{0});
      emit(ProgramStop{});
      if (direction == Direction::Clockwise) emit(StartSpindleClockwise{0}); else emit(StartSpindleCounterclockwise{0});
      break;
    }
    case 890:
      feed(aa, bb, cc);
      emit(Dwell{block.p});
      feed(aa, bb, clear_cc);
      break;
    default:
      break;
  }
  Pose final_position = s.position;
  final_position.*fa = aa;
  final_position.*fb = bb;
  final_position.*fc = clear_cc;
  s.position = final_position;
  if (save_mode != MotionControlMode::ExactPath) {
    emit(SetMotionControlMode{save_mode, save_tolerance});
    if (save_mode == MotionControlMode::Continuous) emit(SetNaivecamTolerance{save_naive});
  }
  cycle.motion = motion;
  cycle.r = r;
  cycle.z = cc;
  if (motion == 730 || motion == 830) cycle.q = block.q;
  if (motion == 820 || motion == 860 || motion == 880 || motion == 890 || motion == 740 || motion == 840) cycle.p = block.p;
  return out;
}

}  // namespace ncbridge::gcode_writer
