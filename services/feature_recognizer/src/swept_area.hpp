#pragma once
// The area a cylindrical tool sweeps in XY when its centre follows polylines: the Minkowski
// sum of the path with the tool's polygonal disk, the union of one "stadium" per segment
// (computed from smaller convex pieces with the same union, docs/recognition.md).
#include <vector>

#include "region.hpp"

namespace ncbridge::feature_recognizer {

// Vertices per full circle so that an inscribed polygon of a circle of `radius` stays within
// `tolerance` of the circle.
int circle_vertex_count(double radius, double tolerance);

// The convex hull of the disks of `radius` at a and b (a disk when a == b), inscribed within
// `tolerance`.
Ring stadium(Point2 a, Point2 b, double radius, double tolerance);

// Removes points of a polyline that lie within `tolerance` of the simplified line
// (Douglas-Peucker); the first and last points stay.
std::vector<Point2> simplify_polyline(const std::vector<Point2>& points, double tolerance);

// The swept area of a disk of `radius` along every polyline. The boundary lies within
// 2 * tolerance of the exact swept area (polygonal disks and path simplification); the cost is
// near-linear in the size of the partial unions' outlines (a tree of unions of neighbours).
Region swept_area(const std::vector<std::vector<Point2>>& polylines, double radius, double tolerance);

// A band of half-width `radius` around the boundary of `region` (used to find where a cut
// crosses the outline of the part).
Region boundary_band(const Region& region, double radius, double tolerance);

}  // namespace ncbridge::feature_recognizer
