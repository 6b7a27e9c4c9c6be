#pragma once
// Fitting ISO 14649 closed profiles to a cutting area's outline: the minimum-area enclosing
// rectangle (rotating calipers on the convex hull), its corner radius from the area the
// corners lack, or a circle.
#include "region.hpp"

namespace ncbridge::feature_recognizer {

struct OrientedRectangle {
  Point2 center;
  double length = 0, width = 0;  // length >= width
  double angle_deg = 0;          // direction of `length` from +X, in [0, 180)
};

OrientedRectangle minimum_area_rectangle(const Ring& points);
double perimeter(const Ring& ring);

// Rectangular (with corner radius and angle), circular, or general closed profile of `outline`
// whose enclosed area is `area`.
Profile fit_closed_profile(const Ring& outline, double area);

}  // namespace ncbridge::feature_recognizer
