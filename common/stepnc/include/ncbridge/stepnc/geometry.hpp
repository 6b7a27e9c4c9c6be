#pragma once
// The ISO 10303-42 geometry the ISO 14649 model uses, as value types, lengths in millimetres.
// Names follow the Part 42 entities (CARTESIAN_POINT, DIRECTION, AXIS2_PLACEMENT_3D, PLANE,
// POLYLINE, TRIMMED_CURVE on a CIRCLE, COMPOSITE_CURVE, BLOCK).
#include <variant>
#include <vector>

namespace ncbridge::stepnc {

struct CartesianPoint {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const CartesianPoint&, const CartesianPoint&) = default;
};

struct Direction {
  double x = 0, y = 0, z = 1;
  friend bool operator==(const Direction&, const Direction&) = default;
};

struct Axis2Placement3d {
  CartesianPoint location;
  Direction axis{0, 0, 1};
  Direction ref_direction{1, 0, 0};
  friend bool operator==(const Axis2Placement3d&, const Axis2Placement3d&) = default;
};

// PLANE (an ELEMENTARY_SURFACE): security planes and the depth planes of features.
struct Plane {
  Axis2Placement3d position;
  friend bool operator==(const Plane&, const Plane&) = default;
};

// BLOCK: a box with a corner at position.location, edges along the placement's x, y, z axes.
struct Block {
  Axis2Placement3d position;
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Block&, const Block&) = default;
};

struct Polyline {
  std::vector<CartesianPoint> points;  // at least two
  friend bool operator==(const Polyline&, const Polyline&) = default;
};

// A TRIMMED_CURVE whose basis curve is a CIRCLE. The circle lies in the plane through
// position.location normal to position.axis; its parameter is the angle in degrees from
// position.ref_direction, counter-clockwise about position.axis. The arc runs from trim_1 to
// trim_2, in the direction of increasing parameter when sense_agreement is true (counter-
// clockwise about the axis), else decreasing. Trims carry both the point and the parameter.
struct TrimmedCircle {
  Axis2Placement3d position;
  double radius = 0;
  CartesianPoint trim_1_point;
  double trim_1_parameter = 0;
  CartesianPoint trim_2_point;
  double trim_2_parameter = 0;
  bool sense_agreement = true;
  friend bool operator==(const TrimmedCircle&, const TrimmedCircle&) = default;
};

// A COMPOSITE_CURVE: segments joined end to start (lines as polylines, arcs as trimmed circles).
// A composite of one polyline is written as a bare POLYLINE.
using CurveSegment = std::variant<Polyline, TrimmedCircle>;
struct CompositeCurve {
  std::vector<CurveSegment> segments;
  friend bool operator==(const CompositeCurve&, const CompositeCurve&) = default;
};

// Swept angle in degrees (0, 360] of an arc, in its direction of travel.
double sweep_degrees(const TrimmedCircle& arc);

}  // namespace ncbridge::stepnc
