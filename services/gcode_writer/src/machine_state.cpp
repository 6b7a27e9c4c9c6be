#include "machine_state.hpp"

#include <cmath>
#include <type_traits>

namespace ncbridge::gcode_writer {

using namespace canonical;

namespace {

constexpr double Pose::*kLinear[6] = {&Pose::x, &Pose::y, &Pose::z, &Pose::u, &Pose::v, &Pose::w};
constexpr double Pose::*kAngular[3] = {&Pose::a, &Pose::b, &Pose::c};

// LinuxCNC keeps the machine still when an origin moves: the program position moves opposite.
void shift(Pose& position, const Pose& old_mm, const Pose& new_mm, double k) {
  for (auto f : kLinear) position.*f += (old_mm.*f - new_mm.*f) / k;
  for (auto f : kAngular) position.*f += old_mm.*f - new_mm.*f;
}

}  // namespace

Pose to_mm(const Pose& p, double k) {
  Pose r = p;
  for (auto f : kLinear) r.*f *= k;
  return r;
}

Pose from_mm(const Pose& p, double k) {
  Pose r = p;
  for (auto f : kLinear) r.*f /= k;
  return r;
}

bool near(double a, double b, double tolerance) { return std::fabs(a - b) <= tolerance; }

bool near(const Pose& a, const Pose& b, double tolerance) {
  for (auto f : kLinear) {
    if (!near(a.*f, b.*f, tolerance)) return false;
  }
  for (auto f : kAngular) {
    if (!near(a.*f, b.*f, tolerance)) return false;
  }
  return true;
}

Pose MachineState::origin_mm() const {
  Pose o = g5x_mm[static_cast<std::size_t>(coord_system)];
  for (auto f : kLinear) o.*f += g92_mm.*f;
  for (auto f : kAngular) o.*f += g92_mm.*f;
  return o;
}

Pose arc_end(const Pose& start, const ArcFeed& arc, Plane plane) {
  Pose end = start;
  switch (plane) {
    case Plane::YZ: end.y = arc.first_end; end.z = arc.second_end; end.x = arc.axis_end_point; break;
    case Plane::XZ: end.z = arc.first_end; end.x = arc.second_end; end.y = arc.axis_end_point; break;
    default: end.x = arc.first_end; end.y = arc.second_end; end.z = arc.axis_end_point; break;
  }
  end.a = arc.a; end.b = arc.b; end.c = arc.c;
  end.u = arc.u; end.v = arc.v; end.w = arc.w;
  return end;
}

void MachineState::apply(const Data& data) {
  std::visit(
      [this](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, UseLengthUnits>) {
          if (d.units != units) {
            ++frame_generation;
            const double k = d.units == Units::Millimeters ? 25.4 : 1.0 / 25.4;
            for (auto f : kLinear) position.*f *= k;
            units = d.units;
          }
        } else if constexpr (std::is_same_v<T, SetG5xOffset>) {
          ++frame_generation;
          const Pose old = origin_mm();
          coord_system = d.index >= 1 && d.index <= 9 ? d.index : 1;
          g5x_mm[static_cast<std::size_t>(coord_system)] = to_mm(d.offset, mm_per_unit());
          shift(position, old, origin_mm(), mm_per_unit());
        } else if constexpr (std::is_same_v<T, SetG92Offset>) {
          ++frame_generation;
          const Pose old = origin_mm();
          g92_mm = to_mm(d.offset, mm_per_unit());
          shift(position, old, origin_mm(), mm_per_unit());
        } else if constexpr (std::is_same_v<T, SetXyRotation>) {
          ++frame_generation;
          rotation[static_cast<std::size_t>(coord_system)] = d.degrees;
        } else if constexpr (std::is_same_v<T, SelectPlane>) {
          plane = d.plane;
        } else if constexpr (std::is_same_v<T, StraightTraverse> || std::is_same_v<T, StraightFeed> ||
                             std::is_same_v<T, StraightProbe>) {
          position = d.end;
        } else if constexpr (std::is_same_v<T, ArcFeed>) {
          position = arc_end(position, d, plane);
        } else if constexpr (std::is_same_v<T, SetFeedRate>) {
          feed_mm = d.rate * mm_per_unit();
        } else if constexpr (std::is_same_v<T, SetFeedMode>) {
          feed_mode = d.mode == 1 ? 1 : 0;
        } else if constexpr (std::is_same_v<T, SetFeedReference>) {
          feed_reference = d.reference;
        } else if constexpr (std::is_same_v<T, SetMotionControlMode>) {
          control = d.mode;
          tolerance = d.tolerance;
        } else if constexpr (std::is_same_v<T, SetNaivecamTolerance>) {
          naive_tolerance = d.tolerance;
        } else if constexpr (std::is_same_v<T, StartSpeedFeedSynch>) {
          synch = true;
          synch_feed_per_revolution = d.feed_per_revolution;
          synch_velocity = d.velocity_mode;
        } else if constexpr (std::is_same_v<T, StopSpeedFeedSynch>) {
          synch = false;
        } else if constexpr (std::is_same_v<T, SetSpindleSpeed>) {
          speed = d.rpm;
        } else if constexpr (std::is_same_v<T, StartSpindleClockwise>) {
          spindle = Direction::Clockwise;
        } else if constexpr (std::is_same_v<T, StartSpindleCounterclockwise>) {
          spindle = Direction::Counterclockwise;
        } else if constexpr (std::is_same_v<T, StopSpindleTurning>) {
          spindle = Direction::Stopped;
        } else if constexpr (std::is_same_v<T, SetSpindleMode>) {
          css_maximum = d.css_maximum;
        } else if constexpr (std::is_same_v<T, UseToolLengthOffset>) {
          ++frame_generation;
          const Pose now = to_mm(d.offset, mm_per_unit());
          shift(position, tool_offset_mm, now, mm_per_unit());
          tool_offset_mm = now;
        } else if constexpr (std::is_same_v<T, SelectTool>) {
          selected_tool = d.tool;
        } else if constexpr (std::is_same_v<T, ChangeTool>) {
          tool_in_spindle = selected_tool < 0 ? tool_in_spindle : selected_tool;
        } else if constexpr (std::is_same_v<T, ChangeToolNumber>) {
          tool_in_spindle = selected_tool = d.number;
        } else if constexpr (std::is_same_v<T, FloodOn>) {
          flood = true;
        } else if constexpr (std::is_same_v<T, FloodOff>) {
          flood = false;
        } else if constexpr (std::is_same_v<T, MistOn>) {
          mist = true;
        } else if constexpr (std::is_same_v<T, MistOff>) {
          mist = false;
        } else if constexpr (std::is_same_v<T, EnableFeedOverride>) {
          feed_override = true;
        } else if constexpr (std::is_same_v<T, DisableFeedOverride>) {
          feed_override = false;
        } else if constexpr (std::is_same_v<T, EnableSpeedOverride>) {
          speed_override = true;
        } else if constexpr (std::is_same_v<T, DisableSpeedOverride>) {
          speed_override = false;
        } else if constexpr (std::is_same_v<T, EnableAdaptiveFeed>) {
          adaptive_feed = true;
        } else if constexpr (std::is_same_v<T, DisableAdaptiveFeed>) {
          adaptive_feed = false;
        } else if constexpr (std::is_same_v<T, EnableFeedHold>) {
          feed_hold = true;
        } else if constexpr (std::is_same_v<T, DisableFeedHold>) {
          feed_hold = false;
        }
      },
      data);
}

}  // namespace ncbridge::gcode_writer
