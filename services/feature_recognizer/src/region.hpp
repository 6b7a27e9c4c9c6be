#pragma once
// A planar point set (the cutting area of a tool, the stock's outline, ...) as an immutable
// value. Coordinates live on a grid of kGrid mm, where Boolean operations are exact; each
// operation rounds the vertices it creates to the grid (region.cpp states the bound).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "ncbridge/feature_recognizer/feature.hpp"

namespace ncbridge::feature_recognizer {

// Grid of the integer coordinates, mm: 1 nm, 10,000 times below the recogniser's 0.01 mm budget.
inline constexpr double kGrid = 1e-6;

using Ring = std::vector<Point2>;  // a closed polygon, last point not repeated

struct Box2 {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  double width() const { return xmax - xmin; }
  double height() const { return ymax - ymin; }
};

struct PolygonWithHoles {
  Ring outer;               // counter-clockwise
  std::vector<Ring> holes;  // clockwise
};

class Region {
 public:
  Region();  // empty
  static Region polygon(const Ring& ring);  // a simple polygon, either orientation
  static Region rectangle(const Box2& box);
  static Region union_of(const std::vector<Ring>& polygons);  // simple polygons
  // The points that closed curves (each may cross itself) wind around a non-zero number of
  // times, their windings summed; curves must not wind negatively where others wind positively.
  static Region from_winding(const std::vector<Ring>& curves);
  // Boundaries as polygons() gives them (outer rings and their holes, any orientation).
  static Region from_polygons(const std::vector<PolygonWithHoles>& polygons);

  // The union of many regions in one sweep (chained unions would redo the growing result each time).
  static Region union_all(const std::vector<Region>& regions);

  Region united(const Region& other) const;
  Region intersected(const Region& other) const;
  Region minus(const Region& other) const;
  Region filled() const;  // every hole closed
  Region translated(double dx, double dy) const;  // the shift rounded to the grid, then exact

  bool empty() const;
  // The same value object (copies of one region): A ∪ A = A ∩ A = A and A − A = ∅ need no
  // arithmetic, which matters when step-downs repeat one swept area many times.
  bool same_as(const Region& other) const { return impl_ == other.impl_; }
  double area() const;
  std::size_t vertex_count() const;  // of every boundary
  std::optional<Box2> bbox() const;
  bool contains(Point2 p) const;  // interior or boundary
  std::vector<Region> components() const;
  std::vector<PolygonWithHoles> polygons() const;  // boundaries, converted to double

 private:
  struct Impl;
  explicit Region(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

// The work the region operations have done on this thread so far: the vertices handed to and
// made by every Boolean operation, and those a point test read. A monotonic count, deterministic
// for a given sequence of operations, that bounds on work are measured with (work_budget.hpp);
// it affects no result.
std::uint64_t region_work();

// area(a ∩ b) / area(a ∪ b), 0 when both are empty.
double overlap_ratio(const Region& a, const Region& b);

// Whether two boxes share more than a boundary (regions in disjoint boxes share no area): the
// cheap test that keeps large programs from comparing every feature with every other exactly.
bool boxes_overlap(const std::optional<Box2>& a, const std::optional<Box2>& b);
// Whether two boxes are apart, not even touching.
bool boxes_apart(const std::optional<Box2>& a, const std::optional<Box2>& b);
std::optional<Box2> box_union(const std::optional<Box2>& a, const std::optional<Box2>& b);

}  // namespace ncbridge::feature_recognizer
