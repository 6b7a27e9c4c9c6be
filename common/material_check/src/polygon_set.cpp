#include "ncbridge/material_check/polygon_set.hpp"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>

namespace ncbridge::material_check {

namespace {

namespace cl = ClipperLib;

cl::IntPoint to_int(Point2 p) {
  return {static_cast<cl::cInt>(std::llround(p.x / kPolygonGrid)), static_cast<cl::cInt>(std::llround(p.y / kPolygonGrid))};
}

Point2 to_point(const cl::IntPoint& p) { return {static_cast<double>(p.X) * kPolygonGrid, static_cast<double>(p.Y) * kPolygonGrid}; }

cl::Paths to_paths(const std::vector<PolygonSet::Ring>& rings) {
  cl::Paths out;
  out.reserve(rings.size());
  for (const auto& r : rings) {
    cl::Path p;
    p.reserve(r.size());
    for (const auto& q : r) {
      const auto ip = to_int(q);
      if (p.empty() || !(p.back() == ip)) p.push_back(ip);
    }
    while (p.size() > 1 && p.front() == p.back()) p.pop_back();
    if (p.size() >= 3) out.push_back(std::move(p));
  }
  return out;
}

std::vector<PolygonSet::Ring> from_tree(const cl::PolyTree& tree) {
  std::vector<PolygonSet::Ring> out;
  for (const cl::PolyNode* node = tree.GetFirst(); node; node = node->GetNext()) {
    PolygonSet::Ring ring;
    ring.reserve(node->Contour.size());
    for (const auto& p : node->Contour) ring.push_back(to_point(p));
    // Outer boundaries counter-clockwise, holes clockwise.
    const bool ccw = signed_area(ring) > 0;
    if (ccw == node->IsHole()) std::reverse(ring.begin(), ring.end());
    out.push_back(std::move(ring));
  }
  return out;
}

std::vector<PolygonSet::Ring> boolean(const std::vector<PolygonSet::Ring>& a, const std::vector<PolygonSet::Ring>& b,
                                      cl::ClipType type) {
  cl::Clipper c;
  c.AddPaths(to_paths(a), cl::ptSubject, true);
  c.AddPaths(to_paths(b), cl::ptClip, true);
  cl::PolyTree tree;
  c.Execute(type, tree, cl::pftNonZero, cl::pftNonZero);
  return from_tree(tree);
}

}  // namespace

double signed_area(const PolygonSet::Ring& ring) {
  double twice = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto& a = ring[i];
    const auto& b = ring[(i + 1) % ring.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return twice / 2;
}

PolygonSet PolygonSet::from_curves(const std::vector<PlanarCurve>& curves, double chord_tolerance) {
  std::vector<Ring> rings;
  for (const auto& c : curves) {
    auto pts = c.points(chord_tolerance);
    if (pts.size() >= 3) rings.push_back(std::move(pts));
  }
  PolygonSet s;
  s.rings_ = boolean(rings, {}, cl::ctUnion);
  return s;
}

PolygonSet PolygonSet::from_rings(std::vector<Ring> rings) {
  PolygonSet s;
  s.rings_ = boolean(rings, {}, cl::ctUnion);
  return s;
}

PolygonSet PolygonSet::rectangle(const Box2& b) {
  return from_rings({{{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}}});
}

PolygonSet PolygonSet::united(const PolygonSet& o) const {
  PolygonSet s;
  s.rings_ = boolean(rings_, o.rings_, cl::ctUnion);
  return s;
}

PolygonSet PolygonSet::intersected(const PolygonSet& o) const {
  PolygonSet s;
  s.rings_ = boolean(rings_, o.rings_, cl::ctIntersection);
  return s;
}

PolygonSet PolygonSet::minus(const PolygonSet& o) const {
  PolygonSet s;
  s.rings_ = boolean(rings_, o.rings_, cl::ctDifference);
  return s;
}

PolygonSet PolygonSet::offset(double delta, double arc_tolerance) const {
  if (rings_.empty()) return {};
  cl::ClipperOffset o(2.0, std::max(arc_tolerance, 2 * kPolygonGrid) / kPolygonGrid);
  o.AddPaths(to_paths(rings_), cl::jtRound, cl::etClosedPolygon);
  cl::PolyTree tree;
  o.Execute(tree, delta / kPolygonGrid);
  PolygonSet s;
  s.rings_ = from_tree(tree);
  return s;
}

double PolygonSet::area() const {
  double a = 0;
  for (const auto& r : rings_) a += signed_area(r);
  return a;
}

Box2 PolygonSet::box() const {
  Box2 b{1e300, 1e300, -1e300, -1e300};
  for (const auto& r : rings_) {
    for (const auto& p : r) {
      b.xmin = std::min(b.xmin, p.x), b.ymin = std::min(b.ymin, p.y);
      b.xmax = std::max(b.xmax, p.x), b.ymax = std::max(b.ymax, p.y);
    }
  }
  return b;
}

bool PolygonSet::contains(Point2 p) const {
  int winding = 0;
  for (const auto& r : rings_) {
    cl::Path path;
    for (const auto& q : r) path.push_back(to_int(q));
    const int in = cl::PointInPolygon(to_int(p), path);
    if (in == -1) return true;  // on the boundary
    if (in == 1) winding += signed_area(r) > 0 ? 1 : -1;
  }
  return winding != 0;
}

std::vector<PolygonSet> PolygonSet::components() const {
  cl::Clipper c;
  c.AddPaths(to_paths(rings_), cl::ptSubject, true);
  cl::PolyTree tree;
  c.Execute(cl::ctUnion, tree, cl::pftNonZero, cl::pftNonZero);
  std::vector<PolygonSet> out;
  // Each outer node with its direct holes; islands inside holes are their own components.
  std::vector<const cl::PolyNode*> stack(tree.Childs.begin(), tree.Childs.end());
  while (!stack.empty()) {
    const cl::PolyNode* outer = stack.back();
    stack.pop_back();
    cl::Paths paths{outer->Contour};
    for (const auto* hole : outer->Childs) {
      paths.push_back(hole->Contour);
      for (const auto* island : hole->Childs) stack.push_back(island);
    }
    cl::Clipper one;
    one.AddPaths(paths, cl::ptSubject, true);
    cl::PolyTree t;
    one.Execute(cl::ctUnion, t, cl::pftEvenOdd, cl::pftEvenOdd);
    PolygonSet s;
    s.rings_ = from_tree(t);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace ncbridge::material_check
