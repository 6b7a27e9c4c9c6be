#pragma once
// Test support: the union of many simple polygons (the tool positions that make a swept area)
// computed with exact constructions (CGAL), then put on the region grid: no vertex of the result
// is off the exact union by more than half a grid diagonal. The independent reference the
// recogniser's swept areas and grid operations (Clipper) are held against; only exact_union.cpp
// sees CGAL.
#include <vector>

#include "region.hpp"

namespace ncbridge::feature_recognizer {

// Polygons that are not simple (after dropping repeated and collinear vertices) add nothing.
Region exact_union(const std::vector<Ring>& polygons);

}  // namespace ncbridge::feature_recognizer
