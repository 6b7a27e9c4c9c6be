#pragma once
// The ISO 10303-42 geometry the ISO 14649 model uses, as value types, lengths in millimetres.
// Names follow the Part 42 entities (CARTESIAN_POINT, DIRECTION, AXIS2_PLACEMENT_3D, PLANE,
// POLYLINE, TRIMMED_CURVE on a CIRCLE, B_SPLINE_CURVE_WITH_KNOTS, COMPOSITE_CURVE, BLOCK).
#include <string>
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

// A B_SPLINE_CURVE_WITH_KNOTS of `degree` over its control points; with weights (one per
// control point, all positive) it is also a RATIONAL_B_SPLINE_CURVE (a NURBS), written as the
// complex instance of both. The knots are the distinct knot values, ascending, each repeated
// knot_multiplicities times; the curve runs over [knots.front(), knots.back()].
enum class KnotType { UniformKnots, QuasiUniformKnots, PiecewiseBezierKnots, Unspecified };
struct BSplineCurve {
  int degree = 1;
  std::vector<CartesianPoint> control_points;
  std::vector<int> knot_multiplicities;
  std::vector<double> knots;
  KnotType knot_spec = KnotType::Unspecified;
  std::vector<double> weights;  // empty: not rational
  friend bool operator==(const BSplineCurve&, const BSplineCurve&) = default;
};

// The curve's point at parameter u (de Boor's algorithm on the weighted points). The curve must
// be valid (bspline_problem() empty).
CartesianPoint bspline_point(const BSplineCurve& curve, double u);
// What makes `curve` no B-spline (ISO 10303-42 constraints_param_b_spline: degree >= 1, as many
// knots counted with multiplicity as control points + degree + 1, multiplicities at most
// degree + 1 and at least 1 inside, knots ascending, weights positive), or "" when it is one.
std::string bspline_problem(const BSplineCurve& curve);
// Points along the curve, ends included, whose chords stay within `tolerance` of it (at most
// about 200000 points for one curve: beyond, chords are not refined further).
std::vector<CartesianPoint> bspline_polyline(const BSplineCurve& curve, double tolerance);

// A COMPOSITE_CURVE: segments joined end to start (lines as polylines, arcs as trimmed circles,
// splines as B-spline curves). A composite of one polyline is written as a bare POLYLINE.
using CurveSegment = std::variant<Polyline, TrimmedCircle, BSplineCurve>;
struct CompositeCurve {
  std::vector<CurveSegment> segments;
  friend bool operator==(const CompositeCurve&, const CompositeCurve&) = default;
};

// Swept angle in degrees (0, 360] of an arc, in its direction of travel.
double sweep_degrees(const TrimmedCircle& arc);

}  // namespace ncbridge::stepnc
