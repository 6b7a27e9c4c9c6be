#pragma once
// Planar point sets as polygons with holes, for Boolean operations and offsets (Clipper, on an
// integer grid of 10 nm). Rings are closed (last point not repeated); outer boundaries are
// counter-clockwise, holes clockwise; the set is what the rings enclose under the non-zero rule.
#include <vector>

#include "ncbridge/material_check/planar_curve.hpp"

namespace ncbridge::material_check {

inline constexpr double kPolygonGrid = 1e-5;  // mm

struct Box2 {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};

class PolygonSet {
 public:
  using Ring = std::vector<Point2>;

  PolygonSet() = default;
  // Closed curves (outer ones counter-clockwise, holes clockwise), arcs as chords within
  // `chord_tolerance`; the chords' ends lie on the arcs.
  static PolygonSet from_curves(const std::vector<PlanarCurve>& curves, double chord_tolerance);
  static PolygonSet from_rings(std::vector<Ring> rings);  // any orientation: normalised (non-zero)
  static PolygonSet rectangle(const Box2& box);

  PolygonSet united(const PolygonSet& other) const;
  PolygonSet intersected(const PolygonSet& other) const;
  PolygonSet minus(const PolygonSet& other) const;
  // Grown (delta > 0) or shrunk (delta < 0) by |delta| with round corners whose chords stay
  // within `arc_tolerance` of the true arcs, their ends on them.
  PolygonSet offset(double delta, double arc_tolerance) const;

  bool empty() const { return rings_.empty(); }
  double area() const;
  Box2 box() const;  // undefined when empty
  bool contains(Point2 p) const;  // inside or on the boundary
  const std::vector<Ring>& rings() const { return rings_; }
  // The connected pieces, each with its holes (rings in the order above).
  std::vector<PolygonSet> components() const;

 private:
  std::vector<Ring> rings_;
};

double signed_area(const PolygonSet::Ring& ring);  // > 0 counter-clockwise

}  // namespace ncbridge::material_check
