#pragma once
// Curves in the XY plane of the program frame (mm): lines and circular arcs, open or closed.
// The features' outlines and the generated toolpaths' loops are made of them; polygons are
// derived from them only where an algorithm needs vertices (within a stated chord tolerance).
#include <variant>
#include <vector>

namespace ncbridge::material_check {

struct Point2 {
  double x = 0, y = 0;
  friend bool operator==(const Point2&, const Point2&) = default;
};

struct LineSegment {
  Point2 a, b;
};

// A circular arc: centre, radius, the angle of its start (radians from +X) and its signed sweep
// (radians; > 0 counter-clockwise). |sweep| may reach 2 pi (a whole circle).
struct ArcSegment {
  Point2 centre;
  double radius = 0;
  double start_angle = 0;
  double sweep = 0;

  Point2 start() const;
  Point2 end() const;
  Point2 at(double fraction) const;  // the point `fraction` (0..1) along the arc
};

using CurveSegment = std::variant<LineSegment, ArcSegment>;

Point2 start_of(const CurveSegment& s);
Point2 end_of(const CurveSegment& s);
double length_of(const CurveSegment& s);

// Segments joined end to start. A closed curve ends where it starts.
struct PlanarCurve {
  std::vector<CurveSegment> segments;
  bool closed = false;

  double length() const;
  // Vertices of a polygonal approximation: arcs as chords whose sagitta is at most
  // `chord_tolerance`, chord ends on the arc. A closed curve's first point is not repeated.
  std::vector<Point2> points(double chord_tolerance) const;
  // Twice the signed area enclosed (> 0 counter-clockwise), arcs exact; closed curves only.
  double signed_area() const;
  PlanarCurve reversed() const;
};

// A rectangle of `length` (along `angle`, radians from +X) by `width`, centred at `centre`,
// its corners rounded with `corner_radius` (0 = sharp), as a closed counter-clockwise curve.
PlanarCurve rounded_rectangle(Point2 centre, double length, double width, double corner_radius, double angle);
PlanarCurve circle(Point2 centre, double radius);  // counter-clockwise, starting at angle 0

}  // namespace ncbridge::material_check
