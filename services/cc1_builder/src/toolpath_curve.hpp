#pragma once
// Appending moves to a cutter-location curve: lines extend the trailing POLYLINE, planar arcs
// become TRIMMED_CURVEs on a CIRCLE, helical arcs a POLYLINE within a chord tolerance.
#include "ncbridge/canonical/call.hpp"
#include <vector>

#include "ncbridge/stepnc/geometry.hpp"

namespace ncbridge::cc1_builder {

// The plane's two axes and its normal, as indices 0..2 (x, y, z), right-handed.
struct PlaneAxes {
  int first = 0, second = 1, normal = 2;
};
PlaneAxes axes_of(canonical::Plane plane);

double get(const stepnc::CartesianPoint& p, int axis);
void set(stepnc::CartesianPoint& p, int axis, double value);
stepnc::Direction unit_axis(int axis, double sign = 1.0);

void append_line(stepnc::CompositeCurve& curve, const stepnc::CartesianPoint& from,
                 const stepnc::CartesianPoint& to);

// An ARC_FEED from `from` to `to` about the centre (`centre_first`, `centre_second`) of the
// plane; rotation > 0 counter-clockwise about the plane normal, |rotation| = turns (LinuxCNC).
// Returns false when the move is helical (it is then appended as a polyline).
bool append_arc(stepnc::CompositeCurve& curve, const stepnc::CartesianPoint& from,
                const stepnc::CartesianPoint& to, double centre_first, double centre_second,
                PlaneAxes axes, int rotation, double chord_tolerance);

// A NURBS_FEED in the XY plane at height `z` (setup frame, mm) from the given control points
// (setup frame) as a B-spline curve with LinuxCNC's clamped uniform knots; rational only when
// the weights differ. Throws std::invalid_argument when order and points make no curve.
stepnc::BSplineCurve nurbs_curve(const std::vector<stepnc::CartesianPoint>& control_points,
                                 const std::vector<double>& weights, int order);
void append_bspline(stepnc::CompositeCurve& curve, stepnc::BSplineCurve spline);

// The lowest Z an arc reaches (an arc out of the XY plane may dip below its ends).
double lowest_z(const stepnc::TrimmedCircle& arc);

}  // namespace ncbridge::cc1_builder
