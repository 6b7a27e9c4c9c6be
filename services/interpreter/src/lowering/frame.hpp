#pragma once
// A programmable frame in the XY plane: the dialect's program coordinates are rotated by
// `rotation_deg` about the frame origin and then shifted by `offset` into the coordinates the
// RS274 executor works in (its G54.. system). Fanuc G68/G69 and local G52-like shifts, Siemens
// TRANS/ATRANS/ROT/AROT and Heidenhain datum shifts all become one of these, so the executor
// only ever sees absolute, unrotated positions and downstream stages need no rotation support.
#include <cmath>
#include <numbers>

namespace ncbridge::interpreter::lowering {

struct Point3 {
  double x = 0, y = 0, z = 0;
};

struct Frame {
  Point3 offset;            // frame origin in executor coordinates
  double rotation_deg = 0;  // counter-clockwise about Z

  bool identity() const { return offset.x == 0 && offset.y == 0 && offset.z == 0 && rotation_deg == 0; }

  // A direction (arc centre offset, hole spacing): rotation only.
  Point3 rotate(const Point3& v) const {
    const double a = rotation_deg * std::numbers::pi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
  }
  Point3 unrotate(const Point3& v) const {
    const double a = -rotation_deg * std::numbers::pi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
  }
  Point3 to_executor(const Point3& p) const {
    Point3 r = rotate(p);
    return {r.x + offset.x, r.y + offset.y, r.z + offset.z};
  }
  Point3 from_executor(const Point3& p) const {
    return unrotate({p.x - offset.x, p.y - offset.y, p.z - offset.z});
  }
  // Additive shift/rotation written in this frame's own coordinates (Siemens ATRANS, AROT).
  void shift_within(const Point3& d) {
    Point3 r = rotate(d);
    offset.x += r.x;
    offset.y += r.y;
    offset.z += r.z;
  }
};

}  // namespace ncbridge::interpreter::lowering
