// Circular and helical arcs, G2/G3, in the IJK (center) and R (radius) forms, with P turns.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "executor.hpp"

namespace ncbridge::interpreter {

using namespace canonical;

namespace {

constexpr double kTiny = 1e-12;
// LinuxCNC's RADIUS_TOLERANCE_INCH/_MM: the R-format reach check and the zero-radius check.
constexpr double kRadiusToleranceInch = 0.00005;
constexpr double kRadiusToleranceMm = 0.00127;
// LinuxCNC's SPIRAL_RELATIVE_TOLERANCE: an IJK arc whose end radius differs from its start
// radius by more than this fraction AND by more than the absolute tolerance is refused.
constexpr double kSpiralRelTolerance = 0.001;
// ... and so is one whose radii differ by more than this many times the absolute tolerance.
constexpr double kSpiralAbsoluteLimitFactor = 100.0;

struct PlaneAxes {
  double Pose::*first;
  double Pose::*second;
  double Pose::*normal;
  char first_letter, second_letter;       // for messages
  char first_offset, second_offset;       // I/J/K letters of the plane
};

PlaneAxes axes_of(Plane plane) {
  switch (plane) {
    case Plane::XZ: return {&Pose::z, &Pose::x, &Pose::y, 'Z', 'X', 'k', 'i'};
    case Plane::YZ: return {&Pose::y, &Pose::z, &Pose::x, 'Y', 'Z', 'j', 'k'};
    default: return {&Pose::x, &Pose::y, &Pose::z, 'X', 'Y', 'i', 'j'};
  }
}

std::string fmt4(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

}  // namespace

void Executor::arc(const BlockCommand& b, int motion, const Pose& end) {
  if (s_.plane != Plane::XY && s_.plane != Plane::XZ && s_.plane != Plane::YZ) {
    fail(b.g_column[kGMotion], "Cannot do an arc in planes G17.1, G18.1, or G19.1");
  }
  if (arc_not_allowed_) {
    fail(b.g_column[kGMotion] ? b.g_column[kGMotion] : 1,
         "The move just after exiting cutter compensation mode must be straight, not an arc");
  }
  bool ijk = b.has('i') || b.has('j') || b.has('k');
  if (!b.has('r') && !ijk) fail(b.g_column[kGMotion], "R i j k words all missing for arc");
  if (b.has('r') && ijk) fail(b.g_column[kGMotion], "Mixed radius-ijk format for arc");
  if (s_.feed_mode == FeedMode::UnitsPerMinute && s_.feed_rate == 0) {
    fail(b.g_column[kGMotion], "Cannot make arc with zero feed rate");
  }
  if (s_.feed_mode == FeedMode::UnitsPerRevolution) {
    if (s_.feed_rate == 0) fail(b.g_column[kGMotion], "Cannot make arc with zero feed rate");
    if (s_.speed == 0) fail(b.g_column[kGMotion], "Cannot feed with zero spindle speed in feed per rev mode");
  }
  if (s_.feed_mode == FeedMode::InverseTime && !b.has('f')) {
    fail(b.g_column[kGMotion], "F word missing with inverse time arc move");
  }
  const PlaneAxes ax = axes_of(s_.plane);
  bool absolute_center = s_.arc_distance == DistanceMode::Absolute;
  double offset1 = 0, offset2 = 0;
  if (ijk) {
    char normal_offset = s_.plane == Plane::XY ? 'k' : s_.plane == Plane::YZ ? 'i' : 'j';
    if (b.has(normal_offset)) {
      const char* names[] = {"K word given for arc in XY plane", "I word given for arc in YZ plane",
                             "J word given for arc in XZ plane"};
      fail(b.col(normal_offset), names[s_.plane == Plane::XY ? 0 : s_.plane == Plane::YZ ? 1 : 2]);
    }
    for (char letter : {ax.first_offset, ax.second_offset}) {
      if (!b.has(letter) && absolute_center) {
        fail(b.g_column[kGMotion], std::string(1, static_cast<char>(letter - 'a' + 'A')) +
                                       " word missing in absolute center arc");
      }
    }
    offset1 = b.has(ax.first_offset) ? b.get(ax.first_offset) : 0.0;
    offset2 = b.has(ax.second_offset) ? b.get(ax.second_offset) : 0.0;
  } else {
    bool has_first = b.has(static_cast<char>(ax.first_letter - 'A' + 'a'));
    bool has_second = b.has(static_cast<char>(ax.second_letter - 'A' + 'a'));
    if (!has_first && !has_second && !b.has_polar()) {
      const char* names[] = {"X and Y words missing for arc in XY plane", "Y and Z words missing for arc in YZ plane",
                             "X and Z words missing for arc in XZ plane"};
      fail(b.g_column[kGMotion], names[s_.plane == Plane::XY ? 0 : s_.plane == Plane::YZ ? 1 : 2]);
    }
  }
  int turns = 1;
  if (b.has('p')) {
    double p = b.get('p');
    turns = static_cast<int>(std::lround(p));
    if (std::fabs(p - turns) > 1e-4 || turns < 1) fail(b.col('p'), "P value not an integer with G2 or G3");
  }

  bool inch = s_.units == Units::Inches;
  double radius_tolerance = inch ? kRadiusToleranceInch : kRadiusToleranceMm;
  double spiral_abs = inch ? arc_tolerance_.inch : arc_tolerance_.mm;
  const Pose& cur = s_.position;
  double c1 = cur.*ax.first, c2 = cur.*ax.second;
  double e1 = end.*ax.first, e2 = end.*ax.second;
  double center1, center2;
  int turn;
  if (b.has('r')) {
    double radius = b.get('r');
    if (e1 == c1 && e2 == c2) fail(b.col('r'), "Current point same as end point of arc");
    double abs_radius = std::fabs(radius);
    double mid1 = (e1 + c1) / 2.0, mid2 = (e2 + c2) / 2.0;
    double half_length = std::hypot(mid1 - e1, mid2 - e2);
    if ((half_length - abs_radius) > radius_tolerance) fail(b.col('r'), "Arc radius too small to reach end point");
    if ((half_length / abs_radius) > (1 - kTiny)) half_length = abs_radius;
    double theta;
    if ((motion == 20 && radius > 0) || (motion == 30 && radius < 0)) {
      theta = std::atan2(e2 - c2, e1 - c1) - std::numbers::pi / 2;
    } else {
      theta = std::atan2(e2 - c2, e1 - c1) + std::numbers::pi / 2;
    }
    double turn2 = std::asin(half_length / abs_radius);
    double offset = abs_radius * std::cos(turn2);
    center1 = mid1 + offset * std::cos(theta);
    center2 = mid2 + offset * std::sin(theta);
  } else {
    center1 = absolute_center ? offset1 : c1 + offset1;
    center2 = absolute_center ? offset2 : c2 + offset2;
    double r1 = std::hypot(center1 - c1, center2 - c2);
    double r2 = std::hypot(center1 - e1, center2 - e2);
    auto where = [&] {  // only for the messages: formatting costs more than the arc
      return "start=(" + std::string(1, ax.first_letter) + fmt4(c1) + "," + ax.second_letter + fmt4(c2) +
             ") center=(" + ax.first_letter + fmt4(center1) + "," + ax.second_letter + fmt4(center2) +
             ") end=(" + ax.first_letter + fmt4(e1) + "," + ax.second_letter + fmt4(e2) + ")";
    };
    if (r1 < radius_tolerance || r2 < radius_tolerance) {
      fail(b.g_column[kGMotion], "Zero-radius arc: " + where() + " r1=" + fmt4(r1) + " r2=" + fmt4(r2));
    }
    double abs_err = std::fabs(r1 - r2);
    double rel_err = abs_err / std::max(r1, r2);
    if (abs_err > kSpiralAbsoluteLimitFactor * spiral_abs || (rel_err > kSpiralRelTolerance && abs_err > spiral_abs)) {
      char tail[128];
      std::snprintf(tail, sizeof tail, " r1=%.4f r2=%.4f abs_err=%.4g rel_err=%.4f%%", r1, r2, abs_err, rel_err * 100);
      fail(b.g_column[kGMotion], "Radius to end of arc differs from radius to start: " + where() + tail);
    }
  }
  turn = motion == 20 ? -turns : turns;

  if (s_.feed_mode == FeedMode::InverseTime) {
    // helix length: angle swept times radius, combined with the travel along the normal
    double radius = std::hypot(c1 - center1, c2 - center2);
    double a0 = std::atan2(c2 - center2, c1 - center1);
    double a1 = std::atan2(e2 - center2, e1 - center1);
    double sweep;
    if (turn > 0) {
      sweep = a1 - a0;
      if (sweep <= 1e-12) sweep += 2 * std::numbers::pi;
      sweep += 2 * std::numbers::pi * (turn - 1);
    } else {
      sweep = a0 - a1;
      if (sweep <= 1e-12) sweep += 2 * std::numbers::pi;
      sweep += 2 * std::numbers::pi * (-turn - 1);
    }
    double normal = end.*ax.normal - cur.*ax.normal;
    set_inverse_time_rate(std::hypot(radius * sweep, normal), b);
  }
  const ArcFeed arc{e1, e2, center1, center2, turn, end.*ax.normal, end.a, end.b, end.c, end.u, end.v, end.w};
  if (comp_.active()) {
    if (comp_.radius() > 0.0) comp_moved_ = true;
    comp_.arc(arc, source_);
  } else {
    emit(arc);
  }
  s_.position = end;
}

}  // namespace ncbridge::interpreter
