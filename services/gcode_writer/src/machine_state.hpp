#pragma once
// The machine state a canonical call stream sets up, as the interpreter's executor keeps it:
// `apply` does to the state what the call says. The writer keeps two: the state the incoming
// calls ask for, and the state the target's reader will be in after the text written so far
// (each dialect writer applies the calls its words make the reader emit). Lengths of offsets
// are held in mm, as the executor holds them, and so are feeds; positions in the current units.
#include <array>
#include <cstdint>

#include "ncbridge/canonical/call.hpp"

namespace ncbridge::gcode_writer {

struct MachineState {
  canonical::Units units = canonical::Units::Millimeters;
  canonical::Plane plane = canonical::Plane::XY;
  // The feed in mm/min (SET_FEED_MODE 0; inverse time arrives as a feed per minute) or mm/rev:
  // a SET_FEED_RATE is in the units of its time, and a later change of units leaves the feed
  // as it is (LinuxCNC's canon layer keeps it in its own units).
  double feed_mm = 0;
  int feed_mode = 0;      // 0 per minute, 1 per revolution
  canonical::FeedReference feed_reference = canonical::FeedReference::Xyz;
  double speed = 0;
  canonical::Direction spindle = canonical::Direction::Stopped;
  double css_maximum = 0;  // SET_SPINDLE_MODE: 0 = constant rpm (G97), else G96 with this limit
  canonical::MotionControlMode control = canonical::MotionControlMode::Continuous;
  double tolerance = 0, naive_tolerance = 0;
  bool mist = false, flood = false;
  bool feed_override = true, speed_override = true, adaptive_feed = false, feed_hold = true;
  int coord_system = 1;  // 1..9 = G54..G59.3
  std::array<canonical::Pose, 10> g5x_mm{};
  std::array<double, 10> rotation{};  // XY rotation of each coordinate system, degrees
  canonical::Pose g92_mm{};           // the G92 offset in effect (zero when off)
  canonical::Pose tool_offset_mm{};
  int selected_tool = -1;  // -1: none selected since the start
  int tool_in_spindle = 0;
  canonical::Pose position{};  // program frame, current units
  bool synch = false;          // START_SPEED_FEED_SYNCH ... STOP
  double synch_feed_per_revolution = 0;
  bool synch_velocity = false;
  // Counts the changes of units, offsets, rotation and tool length offset: a writer whose
  // frame it has brought to this state needs not compare them again until it moves on.
  std::uint64_t frame_generation = 0;

  double mm_per_unit() const { return units == canonical::Units::Inches ? 25.4 : 1.0; }
  canonical::Pose origin_mm() const;  // G5x of the active system + G92
  double active_rotation() const { return rotation[static_cast<std::size_t>(coord_system)]; }

  void apply(const canonical::Data& data);
};

// The end point of an arc as a pose, for the plane it is in.
canonical::Pose arc_end(const canonical::Pose& start, const canonical::ArcFeed& arc, canonical::Plane plane);
// Pose values of a call in the current units converted to mm (linear axes; a, b, c unchanged).
canonical::Pose to_mm(const canonical::Pose& pose, double mm_per_unit);
canonical::Pose from_mm(const canonical::Pose& pose, double mm_per_unit);

bool near(double a, double b, double tolerance = 1e-9);
bool near(const canonical::Pose& a, const canonical::Pose& b, double tolerance = 1e-9);

}  // namespace ncbridge::gcode_writer
