#pragma once
// 2D helpers of the toolpath generator: polygon rings back into lines and arcs (the arcs an
// offset or a feature's outline put there, recovered exactly), loops started at a given point,
// straight links tested against a region.
#include <vector>

#include "ncbridge/material_check/planar_curve.hpp"
#include "ncbridge/material_check/polygon_set.hpp"

namespace ncbridge::toolpath_generator {

using material_check::ArcSegment;
using material_check::CurveSegment;
using material_check::LineSegment;
using material_check::PlanarCurve;
using material_check::Point2;
using material_check::PolygonSet;

inline constexpr double kArcTolerance = 0.0005;  // mm: round joins of offsets, chords of outlines

double distance(Point2 a, Point2 b);

// A closed ring as a closed curve: runs of vertices on one circle (at least three chords of
// equal turning) become one arc through them; the rest stay lines.
PlanarCurve curve_from_ring(const PolygonSet::Ring& ring);
std::vector<PlanarCurve> loops_of(const PolygonSet& region);

// The closest point of a curve to p: its segment index and the fraction along that segment.
struct CurvePlace {
  std::size_t segment = 0;
  double fraction = 0;
  Point2 point;
  double distance = 0;
};
CurvePlace closest_place(const PlanarCurve& curve, Point2 p);

// A closed loop started (and ended) at its point closest to p.
PlanarCurve loop_from(const PlanarCurve& loop, Point2 p);
// The part of an open curve from its start to `place`, and from `place` to its end.
PlanarCurve curve_before(const PlanarCurve& curve, const CurvePlace& place);
PlanarCurve curve_after(const PlanarCurve& curve, const CurvePlace& place);
// The part of a curve from its start over `length` mm (the whole curve when shorter).
PlanarCurve leading_part(const PlanarCurve& curve, double length);

// Whether the straight segment a-b lies inside the region (its boundary included).
bool segment_inside(const PolygonSet& region, Point2 a, Point2 b);

// The region a cutter of `radius` sweeps along the curves (closed ones as loops); open curves
// end round, or square when `square_ends`.
PolygonSet swept_by(const std::vector<PlanarCurve>& curves, double radius, bool square_ends = false);

}  // namespace ncbridge::toolpath_generator

namespace ncbridge::toolpath_generator {
// The pieces of the segment a-b inside the region, in order from a.
std::vector<std::pair<Point2, Point2>> clip_segment(const PolygonSet& region, Point2 a, Point2 b);
// A region less its slivers narrower than `width` (offset in and out again).
PolygonSet without_slivers(const PolygonSet& region, double width);
}  // namespace ncbridge::toolpath_generator
