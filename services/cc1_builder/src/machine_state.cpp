#include "machine_state.hpp"

namespace ncbridge::cc1_builder {

stepnc::CartesianPoint MachineState::to_setup(double x, double y, double z) {
  if (!setup_origin) setup_origin = std::array<double, 3>{g5x[0] + g92[0], g5x[1] + g92[1], g5x[2] + g92[2]};
  return {x * to_mm + frame_shift(0), y * to_mm + frame_shift(1), z * to_mm + frame_shift(2)};
}

double MachineState::axis_to_setup(int axis, double value) {
  if (!setup_origin) setup_origin = std::array<double, 3>{g5x[0] + g92[0], g5x[1] + g92[1], g5x[2] + g92[2]};
  return value * to_mm + frame_shift(axis);
}

double MachineState::frame_shift(int axis) const {
  if (!setup_origin) return 0;
  return g5x[axis] + g92[axis] - (*setup_origin)[axis];
}

stepnc::MillingTechnology MachineState::technology() const {
  stepnc::MillingTechnology t;
  const double rev_per_s = spindle_rpm / 60.0;
  switch (spindle) {
    case canonical::Direction::Clockwise: t.spindle = -rev_per_s; break;
    case canonical::Direction::Counterclockwise: t.spindle = rev_per_s; break;
    case canonical::Direction::Stopped: t.spindle = 0.0; break;
  }
  if (feed_mode == 2) {  // units per revolution: the feed the machine reaches at this speed
    t.feedrate = feed * spindle_rpm / 60000.0;
    t.synchronize_spindle_with_feed = true;
  } else {
    t.feedrate = feed / 60000.0;  // mm/min -> m/s
  }
  return t;
}

stepnc::MillingMachineFunctions MachineState::machine_functions() const {
  stepnc::MillingMachineFunctions f;
  f.coolant = flood;
  if (mist) f.mist = true;
  return f;
}

}  // namespace ncbridge::cc1_builder
