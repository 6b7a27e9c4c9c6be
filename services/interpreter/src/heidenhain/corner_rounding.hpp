#pragma once
// RND: the arc of radius r tangent to the contour element before a corner and the one after it
// (each a straight line or a circular arc), as the TNC inserts it. Plane geometry in the XY plane
// of the program frame; z is carried from the corner.
#include <string>

#include "lowering/frame.hpp"

namespace ncbridge::interpreter::heidenhain {

struct ContourElement {
  lowering::Point3 start, end;
  bool arc = false;
  double cx = 0, cy = 0;  // arc centre
  bool cw = false;        // arc direction
};

struct RoundedCorner {
  bool ok = false;
  std::string error;      // why there is no rounding, when !ok
  lowering::Point3 t1;    // where the element before the corner now ends
  lowering::Point3 t2;    // where the element after it now starts
  lowering::Point3 centre;
  bool ccw = false;       // direction of the rounding arc
};

// `before` ends and `after` starts at the corner.
RoundedCorner round_corner(const ContourElement& before, const ContourElement& after, double radius);

// Centre of a CR arc from `start` to `end` with radius `radius` (R+ the shorter arc, R- the
// longer one) and direction `cw`; false when the radius cannot reach.
bool radius_arc_centre(const lowering::Point3& start, const lowering::Point3& end, double radius, bool cw, double& cx,
                       double& cy);

}  // namespace ncbridge::interpreter::heidenhain
