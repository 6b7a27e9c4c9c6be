// M70 (save the modal state), M71 (forget it), M72 (restore it), M73 (save it, restore it when
// the subroutine returns): LinuxCNC's restore_settings. The restore first sets the length units,
// then runs the other changed modes as one block would (spindle mode, feed mode, F, S, spindle,
// plane, coordinate system, control mode, distance modes, retract mode), then coolant,
// overrides and feed hold. Only what differs from the current state is touched.
#include "executor.hpp"

namespace ncbridge::interpreter {

using namespace canonical;

void Executor::enter_call() { contexts_.emplace_back(); }

void Executor::leave_call() {
  if (contexts_.size() <= 1) return;
  const SavedContext context = contexts_.back();
  contexts_.pop_back();
  if (context.valid && context.restore_on_return) restore_modal_state(context.state);
}

void Executor::do_modal_context(const BlockCommand& b, int m) {
  SavedContext& context = contexts_.back();
  switch (m) {
    case 70:
    case 73:
      context.state = s_;
      context.valid = true;
      context.restore_on_return = m == 73 && contexts_.size() > 1;
      break;
    case 71:
      context.valid = false;
      break;
    default:
      if (!context.valid) {
        fail(b.m_column[kMSpindle], "Cannot restore context from invalid stack frame - missing M70/M73?");
      }
      restore_modal_state(context.state);
      break;
  }
}

void Executor::restore_modal_state(const ModalState& saved) {
  auto run = [this](BlockCommand& block) {
    const Source source = source_;
    const std::string* file = file_;
    block.line = line_;
    execute(block, source, *file);
  };
  BlockCommand block;
  block.reset();
  if (saved.units != s_.units) {
    block.g[kGUnits] = saved.units == Units::Inches ? 200 : 210;
    run(block);
    block.reset();
  }
  auto set = [&block](char letter, double value) {
    const auto bit = static_cast<std::size_t>(letter - 'a');
    block.present |= 1u << bit;
    block.value[bit] = value;
  };
  if (saved.css != s_.css) block.g[kGSpindleMode] = saved.css ? 960 : 970;
  if (saved.feed_mode != s_.feed_mode) {
    block.g[kGFeedMode] = saved.feed_mode == FeedMode::InverseTime ? 930
                        : saved.feed_mode == FeedMode::UnitsPerMinute ? 940 : 950;
  }
  if (saved.feed_rate != s_.feed_rate) set('f', saved.feed_rate);
  if (saved.speed != s_.speed) set('s', saved.speed);
  if (saved.spindle != s_.spindle) {
    block.m[kMSpindle] = saved.spindle == Direction::Clockwise ? 3 : saved.spindle == Direction::Counterclockwise ? 4 : 5;
  }
  if (saved.plane != s_.plane) {
    switch (saved.plane) {
      case Plane::XY: block.g[kGPlane] = 170; break;
      case Plane::XZ: block.g[kGPlane] = 180; break;
      case Plane::YZ: block.g[kGPlane] = 190; break;
      case Plane::UV: block.g[kGPlane] = 171; break;
      case Plane::UW: block.g[kGPlane] = 181; break;
      case Plane::VW: block.g[kGPlane] = 191; break;
    }
  }
  if (saved.coord_system != s_.coord_system) {
    static constexpr int kCodes[10] = {540, 540, 550, 560, 570, 580, 590, 591, 592, 593};
    block.g[kGCoordSystem] = kCodes[saved.coord_system];
  }
  if (saved.control != s_.control || saved.control_tolerance != s_.control_tolerance ||
      saved.naivecam_tolerance != s_.naivecam_tolerance) {
    block.g[kGControl] = saved.control == MotionControlMode::ExactPath ? 610
                       : saved.control == MotionControlMode::ExactStop ? 611 : 640;
    if (saved.control == MotionControlMode::Continuous) {
      set('p', saved.control_tolerance);
      set('q', saved.naivecam_tolerance);
    }
  }
  if (saved.distance != s_.distance) block.g[kGDistance] = saved.distance == DistanceMode::Absolute ? 900 : 910;
  if (saved.arc_distance != s_.arc_distance) {
    block.g[kGArcDistance] = saved.arc_distance == DistanceMode::Absolute ? 901 : 911;
  }
  if (saved.retract != s_.retract) block.g[kGRetract] = saved.retract == RetractMode::OldZ ? 980 : 990;
  run(block);

  if (saved.mist != s_.mist) {
    if (saved.mist) emit(MistOn{}); else emit(MistOff{});
    s_.mist = saved.mist;
  }
  if (saved.flood != s_.flood) {
    if (saved.flood) emit(FloodOn{}); else emit(FloodOff{});
    s_.flood = saved.flood;
  }
  if (saved.feed_override != s_.feed_override) {
    if (saved.feed_override) emit(EnableFeedOverride{0}); else emit(DisableFeedOverride{0});
    s_.feed_override = saved.feed_override;
  }
  if (saved.speed_override != s_.speed_override) {
    if (saved.speed_override) emit(EnableSpeedOverride{0}); else emit(DisableSpeedOverride{0});
    s_.speed_override = saved.speed_override;
  }
  if (saved.feed_hold != s_.feed_hold) {
    if (saved.feed_hold) emit(EnableFeedHold{}); else emit(DisableFeedHold{});
    s_.feed_hold = saved.feed_hold;
  }
}

}  // namespace ncbridge::interpreter
