// Program stops and ends: M0, M1, M60, and the resets of M2/M30 (LinuxCNC convert_stop).
#include "executor.hpp"

namespace ncbridge::interpreter {

using namespace canonical;

bool Executor::do_stop(const BlockCommand& b) {
  int m = b.m[kMStop];
  // The move cutter compensation holds back goes out first (LinuxCNC convert_stop).
  comp_.flush();
  if (m == 0) {
    emit(ProgramStop{});
    return false;
  }
  if (m == 1) {
    emit(OptionalProgramStop{});
    return false;
  }
  if (m == 60) {
    emit(PalletShuttle{});
    emit(ProgramStop{});
    return false;
  }
  // M2 / M30: compensation off without an exit move; LinuxCNC resets the origin to coordinate
  // system 1.
  comp_.reset();
  s_.comp_side = Side::Off;
  Pose old = origin_mm();
  s_.coord_system = 1;
  apply_origin_change(old);
  params_.set_numbered(5220, 1.0);
  emit_g5x();
  emit(SetXyRotation{s_.rotation()});
  if (s_.plane != Plane::XY) {
    emit(SelectPlane{Plane::XY});
    s_.plane = Plane::XY;
  }
  s_.distance = DistanceMode::Absolute;
  s_.feed_mode = FeedMode::UnitsPerMinute;
  emit(SetFeedMode{0, 0});
  s_.feed_rate = 0;
  emit(SetFeedRate{0});
  if (!s_.feed_override) {
    emit(EnableFeedOverride{0});
    s_.feed_override = true;
  }
  s_.speed_override = true;
  emit(StopSpindleTurning{0});
  s_.spindle = Direction::Stopped;
  emit(SetSpindleMode{0, 0.0});
  s_.css = false;
  s_.motion = 10;
  if (s_.mist) {
    emit(MistOff{});
    s_.mist = false;
  }
  if (s_.flood) {
    emit(FloodOff{});
    s_.flood = false;
  }
  if (m == 30) emit(PalletShuttle{});
  emit(ProgramEnd{});
  return true;
}

}  // namespace ncbridge::interpreter
