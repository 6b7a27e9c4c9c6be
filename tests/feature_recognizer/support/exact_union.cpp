// The one translation unit that instantiates CGAL's Boolean set operations.
// Exact_predicates_exact_constructions_kernel: intersections of the many overlapping segments
// of a swept area are computed exactly, so the union never fails or loses faces; the only error
// is the polygonal approximation its caller chose (swept_area.cpp) and the final rounding to
// the region grid.
#include "exact_union.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <iterator>

namespace ncbridge::feature_recognizer {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using CPoint = Kernel::Point_2;
using CPolygon = CGAL::Polygon_2<Kernel>;
using CPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using CPolygonSet = CGAL::Polygon_set_2<Kernel>;

// Removes repeated and collinear consecutive vertices (exactly) so CGAL gets a valid polygon.
CPolygon to_polygon(const Ring& ring) {
  std::vector<CPoint> pts;
  pts.reserve(ring.size());
  for (const auto& p : ring) {
    CPoint q(p.x, p.y);
    if (pts.empty() || pts.back() != q) pts.push_back(q);
  }
  while (pts.size() > 1 && pts.front() == pts.back()) pts.pop_back();
  // Collinear vertices (straight joins and zero-width spikes) make no area; drop them.
  bool changed = true;
  while (changed && pts.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < pts.size() && pts.size() >= 3; ++i) {
      const auto& a = pts[(i + pts.size() - 1) % pts.size()];
      const auto& c = pts[(i + 1) % pts.size()];
      if (CGAL::collinear(a, pts[i], c)) {
        pts.erase(pts.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      }
    }
  }
  CPolygon poly(pts.begin(), pts.end());
  if (poly.size() >= 3 && poly.orientation() == CGAL::CLOCKWISE) poly.reverse_orientation();
  return poly;
}

Ring to_ring(const CPolygon& poly) {
  Ring ring;
  ring.reserve(poly.size());
  for (const auto& v : poly.vertices()) ring.push_back({CGAL::to_double(v.x()), CGAL::to_double(v.y())});
  return ring;
}

}  // namespace

Region exact_union(const std::vector<Ring>& polygons) {
  std::vector<CPolygon> polys;
  polys.reserve(polygons.size());
  for (const auto& ring : polygons) {
    CPolygon poly = to_polygon(ring);
    if (poly.size() >= 3 && poly.is_simple()) polys.push_back(std::move(poly));
  }
  if (polys.empty()) return Region();
  CPolygonSet set;
  set.join(polys.begin(), polys.end());
  std::vector<CPolygonWithHoles> pwhs;
  set.polygons_with_holes(std::back_inserter(pwhs));
  std::vector<PolygonWithHoles> out;
  for (const auto& pwh : pwhs) {
    if (pwh.is_unbounded()) continue;
    PolygonWithHoles p;
    p.outer = to_ring(pwh.outer_boundary());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) p.holes.push_back(to_ring(*h));
    out.push_back(std::move(p));
  }
  return Region::from_polygons(out);
}

}  // namespace ncbridge::feature_recognizer
