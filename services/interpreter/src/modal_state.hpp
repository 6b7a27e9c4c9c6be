#pragma once
// The RS274 machine state the executor keeps between blocks (LinuxCNC's setup_struct, the part
// that is machine semantics rather than parsing). Lengths are in the current program units
// unless the field says mm.
#include <array>

#include "ncbridge/canonical/call.hpp"

namespace ncbridge::interpreter {

enum class DistanceMode { Absolute, Incremental };
enum class FeedMode { UnitsPerMinute, InverseTime, UnitsPerRevolution };
enum class RetractMode { OldZ, RPlane };

struct ModalState {
  canonical::Units units = canonical::Units::Millimeters;
  canonical::Plane plane = canonical::Plane::XY;
  DistanceMode distance = DistanceMode::Absolute;
  DistanceMode arc_distance = DistanceMode::Incremental;
  FeedMode feed_mode = FeedMode::UnitsPerMinute;
  RetractMode retract = RetractMode::RPlane;
  int motion = 800;                 // G code x10 of the active motion mode (G80 = none)
  double feed_rate = 0;
  double speed = 0;
  canonical::Direction spindle = canonical::Direction::Stopped;
  bool css = false;                 // G96
  canonical::MotionControlMode control = canonical::MotionControlMode::Continuous;
  double control_tolerance = 0, naivecam_tolerance = 0;
  bool mist = false, flood = false;
  bool feed_override = true, speed_override = true;
  bool adaptive_feed = false, feed_hold = true;   // M52, M53

  int coord_system = 1;             // 1..9 = G54..G59.3
  std::array<canonical::Pose, 10> g5x_mm{};  // [1..9]
  canonical::Pose g92_mm{};
  bool g92_active = false;          // #5210
  canonical::Pose g28_mm{}, g30_mm{};
  canonical::Pose tool_offset_mm{};
  std::array<double, 10> rotation_deg{};  // G10 L2 R, per coordinate system [1..9]
  double rotation() const { return rotation_deg[static_cast<std::size_t>(coord_system)]; }

  canonical::Pose position{};       // program coordinates of the tool, current units

  int tool_in_spindle = 0;          // tool number
  int selected_tool = -1;           // T word seen (tool number), -1 none
  canonical::Side comp_side = canonical::Side::Off;
  double comp_radius = 0;

  // canned cycles
  bool cycle_initial_level_valid = false;
  double cycle_initial_level = 0;   // G98 level along the plane normal
  double cycle_r = 0, cycle_z = 0, cycle_p = 0, cycle_q = 0, cycle_i = 0, cycle_j = 0, cycle_k = 0;
  int cycle_l = 1;
  std::uint32_t cycle_count = 0;    // holes made so far (CycleTag::cycle_id)

  double mm_per_unit() const { return units == canonical::Units::Inches ? 25.4 : 1.0; }
};

}  // namespace ncbridge::interpreter
