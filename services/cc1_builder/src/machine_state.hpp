#pragma once
// The modal state the canonical calls set, as the builder needs it: units and work offsets (to
// put every point into the setup frame in mm), plane, feed, spindle, coolant, tool, position.
#include <array>
#include <optional>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/stepnc/geometry.hpp"
#include "ncbridge/stepnc/resources.hpp"

namespace ncbridge::cc1_builder {

struct MachineState {
  double to_mm = 1.0;                       // USE_LENGTH_UNITS
  std::array<double, 3> g5x{0, 0, 0};       // mm, machine frame
  std::array<double, 3> g92{0, 0, 0};       // mm
  std::optional<std::array<double, 3>> setup_origin;  // g5x + g92 at the first motion, mm
  canonical::Plane plane = canonical::Plane::XY;
  double feed = 0;                          // mm/min (or mm/rev with feed_mode 2)
  int feed_mode = 0;                        // 0 units/min, 1 inverse time, 2 per revolution
  double spindle_rpm = 0;
  canonical::Direction spindle = canonical::Direction::Stopped;
  bool flood = false;
  bool mist = false;
  int selected_tool = 0;
  int tool = 0;                             // loaded tool number, 0 = none
  std::optional<stepnc::CartesianPoint> position;  // setup frame, mm; unknown before the first motion

  // A program-frame point (current units) in the setup frame, in mm. The first call fixes the
  // setup origin to the work offset then in force.
  stepnc::CartesianPoint to_setup(double x, double y, double z);
  double axis_to_setup(int axis, double value);  // one coordinate, same rule
  // Offset of the current program frame from the setup frame along `axis`, mm.
  double frame_shift(int axis) const;

  stepnc::MillingTechnology technology() const;
  stepnc::MillingMachineFunctions machine_functions() const;
};

}  // namespace ncbridge::cc1_builder
