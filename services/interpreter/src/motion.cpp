// Straight motion: G0, G1, G53, G33, G33.1, and the dispatch of every motion mode.
#include <cmath>

#include "executor.hpp"

namespace ncbridge::interpreter {

using namespace canonical;

namespace {
bool is_canned_cycle(int motion) {
  return motion == 730 || motion == 740 || (motion >= 810 && motion <= 890);
}
}  // namespace

// The end point of a move in program coordinates (LinuxCNC find_ends).
Pose Executor::find_end(const BlockCommand& b, bool g53) const {
  Pose end = s_.position;
  const Pose origin = to_units(origin_mm());
  const Pose tool = to_units(s_.tool_offset_mm);
  struct Axis { char letter; double Pose::*field; };
  static constexpr Axis kAxes[] = {{'x', &Pose::x}, {'y', &Pose::y}, {'z', &Pose::z},
                                   {'a', &Pose::a}, {'b', &Pose::b}, {'c', &Pose::c},
                                   {'u', &Pose::u}, {'v', &Pose::v}, {'w', &Pose::w}};
  for (const Axis& axis : kAxes) {
    if (!b.has(axis.letter)) continue;
    double v = b.get(axis.letter);
    if (g53) {
      end.*axis.field = v - origin.*axis.field - tool.*axis.field;
    } else if (s_.distance == DistanceMode::Incremental) {
      end.*axis.field += v;
    } else {
      end.*axis.field = v;
    }
  }
  if (b.has_polar()) end = polar_end(b, end, g53);
  return end;
}

// Polar coordinates in the XY plane (LinuxCNC find_ends): in G90, `@` is the radius and `^` the
// angle about the origin, a missing one kept from the current point; in G91, `@` adds to the
// current point's radius and `^` to its angle (the radius first).
Pose Executor::polar_end(const BlockCommand& b, Pose end, bool g53) const {
  constexpr double kDegree = 3.14159265358979323846 / 180.0;
  if (g53) fail(b.polar_column(), "Cannot use polar coordinates with G53");
  double& x = end.x;
  double& y = end.y;
  if (s_.distance == DistanceMode::Absolute) {
    if (b.has_polar_radius && b.has_polar_angle) {
      x = b.polar_radius * std::cos(b.polar_angle * kDegree);
      y = b.polar_radius * std::sin(b.polar_angle * kDegree);
    } else if (b.has_polar_radius) {
      if (x == 0 && y == 0) fail(b.polar_radius_column, "Must specify angle in polar coordinate if at the origin");
      const double theta = std::atan2(y, x);
      x = b.polar_radius * std::cos(theta);
      y = b.polar_radius * std::sin(theta);
    } else {
      const double radius = std::hypot(y, x);
      x = radius * std::cos(b.polar_angle * kDegree);
      y = radius * std::sin(b.polar_angle * kDegree);
    }
    return end;
  }
  if (b.has_polar_radius) {
    if (x == 0 && y == 0) {
      fail(b.polar_radius_column, "Incremental motion with polar coordinates is indeterminate when at the origin");
    }
    const double theta = std::atan2(y, x);
    const double radius = std::hypot(y, x) + b.polar_radius;
    x = radius * std::cos(theta);
    y = radius * std::sin(theta);
  }
  if (b.has_polar_angle) {
    if (x == 0 && y == 0) fail(b.polar_angle_column, "G91 motion with polar coordinates is indeterminate when at the origin");
    const double theta = std::atan2(y, x) + b.polar_angle * kDegree;
    const double radius = std::hypot(y, x);
    x = radius * std::cos(theta);
    y = radius * std::sin(theta);
  }
  return end;
}

void Executor::set_inverse_time_rate(double length, const BlockCommand& b) {
  // F is the inverse of the time in minutes: feed = length * F
  emit(SetFeedRate{length * b.get('f')});
}

void Executor::straight(bool feed, const Pose& end, const BlockCommand* b) {
  if (feed) {
    if (b != nullptr && s_.feed_mode == FeedMode::InverseTime) {
      const Pose& p = s_.position;
      double length = std::sqrt((end.x - p.x) * (end.x - p.x) + (end.y - p.y) * (end.y - p.y) +
                                (end.z - p.z) * (end.z - p.z));
      if (length == 0) {
        length = std::sqrt((end.a - p.a) * (end.a - p.a) + (end.b - p.b) * (end.b - p.b) +
                           (end.c - p.c) * (end.c - p.c));
      }
      set_inverse_time_rate(length, *b);
    }
  }
  if (comp_.active()) {
    if (comp_.radius() > 0.0) comp_moved_ = true;
    comp_.straight(feed, to_comp(end), source_);
  } else if (feed) {
    emit(StraightFeed{end});
  } else {
    emit(StraightTraverse{end});
  }
  s_.position = end;
}

void Executor::do_motion(const BlockCommand& b, int motion, bool g53) {
  if (g53 && s_.comp_side != Side::Off) fail(b.g_column[kGNonModal], "Cannot use g53 with cutter radius comp");
  if (!is_canned_cycle(motion)) s_.cycle_initial_level_valid = false;
  switch (motion) {
    case 0: {
      Pose end = find_end(b, g53);
      arc_not_allowed_ = false;
      straight(false, end, &b);
      break;
    }
    case 10: {
      if (s_.feed_mode == FeedMode::UnitsPerMinute && s_.feed_rate == 0) {
        fail(b.g_column[kGMotion], "Cannot do G1 with zero feed rate");
      }
      if (s_.feed_mode == FeedMode::UnitsPerRevolution && s_.feed_rate == 0) {
        fail(b.g_column[kGMotion], "Cannot do G1 with zero feed rate");
      }
      if (s_.feed_mode == FeedMode::InverseTime && !b.has('f')) {
        fail(b.g_column[kGMotion], "F word missing with inverse time G1 move");
      }
      Pose end = find_end(b, g53);
      arc_not_allowed_ = false;
      straight(true, end, &b);
      break;
    }
    case 20:
    case 30:
      arc(b, motion, find_end(b, false));
      break;
    case 330:
    case 331: {
      if (s_.spindle == Direction::Stopped) {
        fail(b.g_column[kGMotion], motion == 330 ? "Spindle not turning in G33" : "Spindle not turning in G33.1");
      }
      if (!b.has('k')) fail(b.g_column[kGMotion], "K word missing with G33");
      Pose end = find_end(b, false);
      emit(StartSpeedFeedSynch{0, b.get('k'), false});
      if (motion == 330) {
        emit(StraightFeed{end});
      } else {
        emit(RigidTap{end, 1.0});
        end = s_.position;  // rigid tapping returns to the start
      }
      emit(StopSpeedFeedSynch{});
      s_.position = end;
      break;
    }
    case 800:
      emit(Comment{"interpreter: motion mode set to none"});
      break;
    case 50:
    case 51:
      spline(b, motion);
      return;  // G5 and G5.1 leave the motion mode as it was
    case 52:
      nurbs_point(b);
      return;
    case 382:
    case 383:
    case 384:
    case 385:
      probe(b, motion);
      return;
    default:
      if (is_canned_cycle(motion)) {
        canned_cycle(b, motion);
        return;  // canned_cycle sets the motion mode itself
      }
      fail(b.g_column[kGMotion], "G" + std::to_string(motion / 10) + (motion % 10 ? "." + std::to_string(motion % 10) : "") +
                                     " is not supported by this interpreter");
  }
  s_.motion = motion;
}

}  // namespace ncbridge::interpreter
