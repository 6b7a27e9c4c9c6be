// The one translation unit that instantiates CGAL's Boolean set operations.
// Exact_predicates_exact_constructions_kernel: intersections of the many overlapping segments
// of a swept area are computed exactly, so unions never fail or lose faces; the only error in
// a region is the polygonal approximation its caller chose (see swept_area.cpp).
#include "region.hpp"

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

double polygon_area(const CPolygon& poly) { return CGAL::to_double(poly.area()); }

}  // namespace

struct Region::Impl {
  CPolygonSet set;
};

Region::Region() : impl_(std::make_shared<Impl>()) {}
Region::Region(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

Region Region::polygon(const Ring& ring) {
  auto impl = std::make_shared<Impl>();
  CPolygon poly = to_polygon(ring);
  if (poly.size() >= 3 && poly.is_simple()) impl->set.insert(poly);
  return Region(std::move(impl));
}

Region Region::rectangle(const Box2& box) {
  return polygon({{box.xmin, box.ymin}, {box.xmax, box.ymin}, {box.xmax, box.ymax}, {box.xmin, box.ymax}});
}

Region Region::union_of(const std::vector<Ring>& polygons) {
  std::vector<CPolygon> polys;
  polys.reserve(polygons.size());
  for (const auto& ring : polygons) {
    CPolygon poly = to_polygon(ring);
    if (poly.size() >= 3 && poly.is_simple()) polys.push_back(std::move(poly));
  }
  auto impl = std::make_shared<Impl>();
  if (!polys.empty()) impl->set.join(polys.begin(), polys.end());
  return Region(std::move(impl));
}

Region Region::united(const Region& other) const {
  if (same_as(other) || other.empty()) return *this;
  if (empty()) return other;
  auto impl = std::make_shared<Impl>(*impl_);
  impl->set.join(other.impl_->set);
  return Region(std::move(impl));
}

Region Region::translated(double dx, double dy) const {
  const Kernel::Vector_2 shift(dx, dy);
  auto move = [&](const CPolygon& p) {
    CPolygon out;
    for (const auto& v : p.vertices()) out.push_back(v + shift);
    return out;
  };
  std::vector<CPolygonWithHoles> parts;
  impl_->set.polygons_with_holes(std::back_inserter(parts));
  auto impl = std::make_shared<Impl>();
  for (const auto& pwh : parts) {
    CPolygonWithHoles moved(move(pwh.outer_boundary()));
    for (const auto& hole : pwh.holes()) moved.add_hole(move(hole));
    impl->set.insert(moved);
  }
  return Region(std::move(impl));
}

Region Region::intersected(const Region& other) const {
  if (same_as(other)) return *this;
  auto impl = std::make_shared<Impl>(*impl_);
  impl->set.intersection(other.impl_->set);
  return Region(std::move(impl));
}

Region Region::minus(const Region& other) const {
  if (same_as(other)) return Region();
  if (other.empty()) return *this;
  auto impl = std::make_shared<Impl>(*impl_);
  impl->set.difference(other.impl_->set);
  return Region(std::move(impl));
}

Region Region::filled() const {
  std::vector<CPolygonWithHoles> pwhs;
  impl_->set.polygons_with_holes(std::back_inserter(pwhs));
  auto impl = std::make_shared<Impl>();
  for (const auto& pwh : pwhs) {
    if (!pwh.is_unbounded()) impl->set.join(pwh.outer_boundary());
  }
  return Region(std::move(impl));
}

bool Region::empty() const { return impl_->set.is_empty(); }

double Region::area() const {
  std::vector<CPolygonWithHoles> pwhs;
  impl_->set.polygons_with_holes(std::back_inserter(pwhs));
  double total = 0;
  for (const auto& pwh : pwhs) {
    if (pwh.is_unbounded()) continue;
    total += polygon_area(pwh.outer_boundary());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) total -= std::abs(polygon_area(*h));
  }
  return total;
}

std::optional<Box2> Region::bbox() const {
  std::vector<CPolygonWithHoles> pwhs;
  impl_->set.polygons_with_holes(std::back_inserter(pwhs));
  std::optional<Box2> box;
  for (const auto& pwh : pwhs) {
    if (pwh.is_unbounded()) continue;
    for (const auto& v : pwh.outer_boundary().vertices()) {
      const double x = CGAL::to_double(v.x()), y = CGAL::to_double(v.y());
      if (!box) box = Box2{x, y, x, y};
      box->xmin = std::min(box->xmin, x);
      box->ymin = std::min(box->ymin, y);
      box->xmax = std::max(box->xmax, x);
      box->ymax = std::max(box->ymax, y);
    }
  }
  return box;
}

bool Region::contains(Point2 p) const {
  return impl_->set.oriented_side(CPoint(p.x, p.y)) != CGAL::ON_NEGATIVE_SIDE;
}

std::vector<Region> Region::components() const {
  std::vector<CPolygonWithHoles> pwhs;
  impl_->set.polygons_with_holes(std::back_inserter(pwhs));
  std::vector<Region> out;
  for (const auto& pwh : pwhs) {
    if (pwh.is_unbounded()) continue;
    auto impl = std::make_shared<Impl>();
    impl->set.insert(pwh);
    out.push_back(Region(std::move(impl)));
  }
  return out;
}

std::vector<PolygonWithHoles> Region::polygons() const {
  std::vector<CPolygonWithHoles> pwhs;
  impl_->set.polygons_with_holes(std::back_inserter(pwhs));
  std::vector<PolygonWithHoles> out;
  for (const auto& pwh : pwhs) {
    if (pwh.is_unbounded()) continue;
    PolygonWithHoles p;
    p.outer = to_ring(pwh.outer_boundary());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) p.holes.push_back(to_ring(*h));
    out.push_back(std::move(p));
  }
  return out;
}

bool boxes_overlap(const std::optional<Box2>& a, const std::optional<Box2>& b) {
  return a && b && a->xmin < b->xmax && b->xmin < a->xmax && a->ymin < b->ymax && b->ymin < a->ymax;
}

std::optional<Box2> box_union(const std::optional<Box2>& a, const std::optional<Box2>& b) {
  if (!a) return b;
  if (!b) return a;
  return Box2{std::min(a->xmin, b->xmin), std::min(a->ymin, b->ymin), std::max(a->xmax, b->xmax), std::max(a->ymax, b->ymax)};
}

double overlap_ratio(const Region& a, const Region& b) {
  const double inter = a.intersected(b).area();
  const double uni = a.area() + b.area() - inter;
  return uni > 0 ? inter / uni : 0;
}

}  // namespace ncbridge::feature_recognizer
