#pragma once
// Points, planes and arcs: the small amount of geometry every part of the optimizer shares.
#include <cmath>

#include "ncbridge/toolpath_optimizer/toolpath.hpp"

namespace ncbridge::toolpath_optimizer {

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
inline double distance(Vec3 a, Vec3 b) { return norm(a - b); }

// A point in a plane's axes: first and second as canonical ARC_FEED orders them (XY: x,y;
// YZ: y,z; XZ: z,x) and the normal axis (z, x, y).
struct PlanePoint {
  double first = 0, second = 0, normal = 0;
};
inline PlanePoint to_plane(Vec3 p, canonical::Plane plane) {
  switch (plane) {
    case canonical::Plane::YZ: return {p.y, p.z, p.x};
    case canonical::Plane::XZ: return {p.z, p.x, p.y};
    default: return {p.x, p.y, p.z};
  }
}
Vec3 from_plane(PlanePoint p, canonical::Plane plane);

// Distance from p to the segment [a, b].
double distance_to_segment(Vec3 p, Vec3 a, Vec3 b);

// An arc motion resolved: centre, radii at both ends, start angle and signed sweep (positive =
// counter-clockwise in the plane's axes), the normal axis at both ends. A controller whose end
// radius differs slightly from the start radius moves a spiral between them (LinuxCNC); at()
// does the same, so at(1) is the programmed end exactly.
struct ArcPath {
  canonical::Plane plane = canonical::Plane::XY;
  double centre_first = 0, centre_second = 0;
  double start_radius = 0, end_radius = 0;
  double start_angle = 0, sweep = 0;
  double start_normal = 0, end_normal = 0;

  Vec3 at(double fraction) const;
  double length() const;  // along the helix
};
ArcPath resolve_arc(const Motion& arc);

// Signed sweep from angle a0 to a1 turning ccw (result in (0, 2pi]) or cw (in [-2pi, 0)). Equal
// angles give a full turn.
double sweep_between(double a0, double a1, bool ccw);

// Length of a motion's path (line, or helix for an arc).
double path_length(const Motion& m);

constexpr double kPi = 3.14159265358979323846;

}  // namespace ncbridge::toolpath_optimizer
