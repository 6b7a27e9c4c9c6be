// Boolean operations on a fixed integer grid (Clipper 6, integer-exact): every coordinate is
// snapped to kGrid, and a vertex that an operation creates where two edges cross is rounded to
// it. So an operation moves the boundary by at most half a grid diagonal (0.71e-6 mm); a region
// made by k chained operations is within k * 0.71e-6 mm of the exact result of its inputs, far
// inside the recogniser's 0.01 mm budget (docs/recognition.md, "Geometry and error bounds").
#include "region.hpp"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <atomic>
#include <mutex>

namespace ncbridge::feature_recognizer {
namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

constexpr double kScale = 1.0 / kGrid;

// The count region_work() reports (an instrument, read for work limits; no result depends on it).
thread_local std::uint64_t work_done = 0;
// Well inside Clipper's full range, so sums and products of two coordinates never overflow.
constexpr double kLimit = 1e15;

cInt to_grid(double v) {
  if (!std::isfinite(v)) v = v > 0 ? kLimit : -kLimit;  // NaN counts as -limit: never UB
  return static_cast<cInt>(std::llround(std::clamp(v * kScale, -kLimit, kLimit)));
}

double from_grid(cInt v) { return static_cast<double>(v) * kGrid; }

Path to_path(const Ring& ring) {
  Path path;
  path.reserve(ring.size());
  for (const auto& p : ring) {
    IntPoint q(to_grid(p.x), to_grid(p.y));
    if (path.empty() || !(path.back() == q)) path.push_back(q);
  }
  while (path.size() > 1 && path.front() == path.back()) path.pop_back();
  return path;
}

Ring to_ring(const Path& path) {
  Ring ring;
  ring.reserve(path.size());
  for (const auto& q : path) ring.push_back({from_grid(q.X), from_grid(q.Y)});
  return ring;
}

// A large region (a face milled over the whole part) is met by many small ones (each pocket
// asks how much of it was cut before). It is cut once into tiles of at most kTileVertices
// vertices, and an operation with a small region reads only the tiles under that region's box.
constexpr std::size_t kTileVertices = 256;
constexpr std::size_t kTiledAbove = 2048;  // vertices

struct GridBox {
  cInt xmin, ymin, xmax, ymax;
  bool touches(const GridBox& o) const { return xmin <= o.xmax && o.xmin <= xmax && ymin <= o.ymax && o.ymin <= ymax; }
  Path ring() const { return {{xmin, ymin}, {xmax, ymin}, {xmax, ymax}, {xmin, ymax}}; }
};

struct Tile {
  GridBox box;
  Paths paths;  // the region within `box`: outer contours positive, holes negative
};

std::size_t count_vertices(const Paths& paths) {
  std::size_t n = 0;
  for (const auto& p : paths) n += p.size();
  return n;
}

Paths clip_to(const Paths& paths, const GridBox& box) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(paths, ClipperLib::ptSubject, true);
  clipper.AddPath(box.ring(), ClipperLib::ptClip, true);
  Paths out;
  clipper.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  work_done += count_vertices(paths) + 4 + count_vertices(out);
  return out;
}

void cut_into_tiles(const Paths& paths, const GridBox& box, int depth, std::vector<Tile>& out) {
  const bool splittable = box.xmax - box.xmin >= 2 || box.ymax - box.ymin >= 2;
  if (count_vertices(paths) <= kTileVertices || depth >= 24 || !splittable) {
    out.push_back({box, paths});
    return;
  }
  GridBox low = box, high = box;
  if (box.xmax - box.xmin >= box.ymax - box.ymin) {
    low.xmax = high.xmin = box.xmin + (box.xmax - box.xmin) / 2;
  } else {
    low.ymax = high.ymin = box.ymin + (box.ymax - box.ymin) / 2;
  }
  for (const auto& half : {low, high}) {
    Paths piece = clip_to(paths, half);
    if (!piece.empty()) cut_into_tiles(piece, half, depth + 1, out);
  }
}

GridBox grid_box(const Box2& b) { return {to_grid(b.xmin), to_grid(b.ymin), to_grid(b.xmax), to_grid(b.ymax)}; }

GridBox path_box(const Path& path) {
  GridBox b{path.front().X, path.front().Y, path.front().X, path.front().Y};
  for (const auto& q : path) {
    b.xmin = std::min(b.xmin, q.X), b.ymin = std::min(b.ymin, q.Y);
    b.xmax = std::max(b.xmax, q.X), b.ymax = std::max(b.ymax, q.Y);
  }
  return b;
}

// Edges up to this long (in grid units, 2 m) have exact 64-bit cross products.
constexpr cInt kExactSide = cInt{1} << 31;

// Whether a closed path turns one way at every vertex and once around: a convex polygon, in
// either orientation (integer cross products, so exact; longer edges answer no).
bool is_convex(const Path& path) {
  const std::size_t n = path.size();
  if (n < 3) return false;
  int sign = 0;
  double turning = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = path[i];
    const auto& b = path[(i + 1) % n];
    const auto& c = path[(i + 2) % n];
    const cInt d[4] = {b.X - a.X, b.Y - a.Y, c.X - b.X, c.Y - b.Y};
    if (std::any_of(std::begin(d), std::end(d), [](cInt v) { return v > kExactSide || v < -kExactSide; })) {
      return false;  // products could overflow: not decided here
    }
    const cInt cross = d[0] * d[3] - d[1] * d[2];
    const int s = cross > 0 ? 1 : cross < 0 ? -1 : 0;
    if (s == 0 || (sign != 0 && s != sign)) return false;  // collinear or turning back
    sign = s;
    const double dot = static_cast<double>(d[0]) * static_cast<double>(d[2]) + static_cast<double>(d[1]) * static_cast<double>(d[3]);
    turning += std::atan2(static_cast<double>(cross), dot);
  }
  return std::abs(std::abs(turning) - 2 * 3.14159265358979323846) < 1.0;  // not a star
}

}  // namespace

struct Region::Impl {
  Impl() = default;
  Impl(const Impl& other)  // the tiles are not copied: made again if needed
      : components(other.components), area(other.area), box(other.box), vertices(other.vertices), is_box(other.is_box) {}

  struct Component {
    Path outer;   // positive area (counter-clockwise)
    Paths holes;  // negative area
    bool nested = false;  // lies in a hole of another component
    // Filled in by finish():
    GridBox box{};
    std::vector<char> convex_holes;
    bool operator==(const Component& o) const { return nested == o.nested && outer == o.outer && holes == o.holes; }
  };
  std::vector<Component> components;
  double area = 0;
  std::optional<Box2> box;
  std::size_t vertices = 0;
  bool is_box = false;  // an axis-parallel rectangle

  // The same point set in the same representation (regions made alike from equal inputs).
  bool equals(const Impl& o) const { return area == o.area && vertices == o.vertices && components == o.components; }

  // Whether the interior of `g` lies in no component: each component near it has a convex hole
  // that holds all of `g`.
  bool box_in_holes(const GridBox& g) const {
    if (tiled()) return false;
    const IntPoint corners[4] = {{g.xmin, g.ymin}, {g.xmax, g.ymin}, {g.xmax, g.ymax}, {g.xmin, g.ymax}};
    for (const auto& c : components) {
      if (!c.box.touches(g)) continue;
      bool held = false;
      for (std::size_t h = 0; h < c.holes.size() && !held; ++h) {
        held = c.convex_holes[h] && std::all_of(std::begin(corners), std::end(corners), [&](const IntPoint& q) {
                 return ClipperLib::PointInPolygon(q, c.holes[h]) == 1;
               });
      }
      if (!held) return false;
    }
    return true;
  }

  // Whether `g` lies within this region, which is a rectangle.
  bool box_holds(const GridBox& g) const {
    if (!is_box) return false;
    const auto& b = components.front().box;
    return b.xmin <= g.xmin && g.xmax <= b.xmax && b.ymin <= g.ymin && g.ymax <= b.ymax;
  }

  bool tiled() const { return vertices > kTiledAbove; }

  const std::vector<Tile>& tiles() const {
    std::call_once(tiles_made_, [&] {
      if (box) cut_into_tiles(paths(), grid_box(*box), 0, tiles_);
    });
    return tiles_;
  }

  // Contours that cover at least the part of the region inside `near` (all of them for a small
  // region): what an operation with a region inside `near` needs.
  // Tiles pay off for a region met again and again by small ones (a face, the band along the
  // part's outline); a large region met a few times only (what earlier features removed near
  // one) is used whole.
  Paths paths_near(const std::optional<Box2>& near) const {
    if (!tiled() || !near) return paths();
    const double near_area = std::max(0.0, near->xmax - near->xmin) * std::max(0.0, near->ymax - near->ymin);
    const double own_area = std::max(0.0, box->xmax - box->xmin) * std::max(0.0, box->ymax - box->ymin);
    if (near_area >= 0.25 * own_area || small_queries_.fetch_add(1, std::memory_order_relaxed) < 8) return paths();
    const GridBox g = grid_box(*near);
    Paths out;
    for (const auto& tile : tiles()) {
      if (tile.box.touches(g)) out.insert(out.end(), tile.paths.begin(), tile.paths.end());
    }
    return out;
  }

  // Every contour, outer ones positive and holes negative: nonzero winding is 1 exactly inside.
  Paths paths() const {
    Paths out;
    for (const auto& c : components) {
      out.push_back(c.outer);
      out.insert(out.end(), c.holes.begin(), c.holes.end());
    }
    return out;
  }

  void finish() {
    area = 0;
    box.reset();
    vertices = 0;
    for (auto& c : components) {
      c.box = path_box(c.outer);
      c.convex_holes.clear();
      for (const auto& h : c.holes) c.convex_holes.push_back(is_convex(h));
      vertices += c.outer.size();
      for (const auto& h : c.holes) vertices += h.size();
      area += ClipperLib::Area(c.outer);
      for (const auto& h : c.holes) area += ClipperLib::Area(h);  // negative
      for (const auto& q : c.outer) {
        const double x = from_grid(q.X), y = from_grid(q.Y);
        if (!box) box = Box2{x, y, x, y};
        box->xmin = std::min(box->xmin, x);
        box->ymin = std::min(box->ymin, y);
        box->xmax = std::max(box->xmax, x);
        box->ymax = std::max(box->ymax, y);
      }
    }
    area *= kGrid * kGrid;
    is_box = false;
    if (components.size() == 1 && components.front().holes.empty() && components.front().outer.size() == 4) {
      const auto& b = components.front().box;
      is_box = std::all_of(components.front().outer.begin(), components.front().outer.end(), [&](const IntPoint& q) {
        return (q.X == b.xmin || q.X == b.xmax) && (q.Y == b.ymin || q.Y == b.ymax);
      });
    }
  }

  void add_tree(const ClipperLib::PolyNode& node, bool nested) {
    // `node` is an outer contour; its children are holes, whose children are islands.
    if (node.Contour.size() < 3) return;
    Component c;
    c.outer = node.Contour;
    c.nested = nested;
    for (const auto* hole : node.Childs) {
      if (hole->Contour.size() >= 3) c.holes.push_back(hole->Contour);
    }
    components.push_back(std::move(c));
    for (const auto* hole : node.Childs) {
      for (const auto* island : hole->Childs) add_tree(*island, true);
    }
  }

  static std::shared_ptr<Impl> from_tree(const ClipperLib::PolyTree& tree) {
    auto impl = std::make_shared<Impl>();
    for (const auto* node : tree.Childs) impl->add_tree(*node, false);
    impl->finish();
    return impl;
  }

  static std::shared_ptr<Impl> execute(ClipperLib::ClipType type, const Paths& subject, const Paths& clip) {
    ClipperLib::Clipper clipper;
    clipper.AddPaths(subject, ClipperLib::ptSubject, true);
    clipper.AddPaths(clip, ClipperLib::ptClip, true);
    ClipperLib::PolyTree tree;
    clipper.Execute(type, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    auto impl = from_tree(tree);
    work_done += count_vertices(subject) + count_vertices(clip) + impl->vertices;
    return impl;
  }

 private:
  mutable std::atomic<int> small_queries_{0};  // operations with a region in a small part of this one's box
  mutable std::once_flag tiles_made_;
  mutable std::vector<Tile> tiles_;
};

Region::Region() : impl_(std::make_shared<Impl>()) {}
Region::Region(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

Region Region::polygon(const Ring& ring) { return union_of({ring}); }

Region Region::rectangle(const Box2& box) {
  return polygon({{box.xmin, box.ymin}, {box.xmax, box.ymin}, {box.xmax, box.ymax}, {box.xmin, box.ymax}});
}

Region Region::union_of(const std::vector<Ring>& polygons) {
  Paths paths;
  paths.reserve(polygons.size());
  for (const auto& ring : polygons) {
    Path path = to_path(ring);
    if (path.size() < 3) continue;
    if (!ClipperLib::Orientation(path)) ClipperLib::ReversePath(path);  // either orientation adds area
    paths.push_back(std::move(path));
  }
  if (paths.empty()) return Region();
  if (paths.size() == 1 && is_convex(paths.front())) {  // already simple: nothing to resolve
    auto impl = std::make_shared<Impl>();
    impl->components.push_back({std::move(paths.front()), {}, false, {}, {}});
    impl->finish();
    return Region(std::move(impl));
  }
  return Region(Impl::execute(ClipperLib::ctUnion, paths, {}));
}

Region Region::from_winding(const std::vector<Ring>& curves) {
  Paths paths;
  paths.reserve(curves.size());
  for (const auto& ring : curves) {
    Path path = to_path(ring);
    if (path.size() >= 3) paths.push_back(std::move(path));
  }
  if (paths.empty()) return Region();
  return Region(Impl::execute(ClipperLib::ctUnion, paths, {}));
}

Region Region::from_polygons(const std::vector<PolygonWithHoles>& polygons) {
  Paths paths;
  for (const auto& pwh : polygons) {
    Path outer = to_path(pwh.outer);
    if (outer.size() < 3) continue;
    if (!ClipperLib::Orientation(outer)) ClipperLib::ReversePath(outer);
    paths.push_back(std::move(outer));
    for (const auto& ring : pwh.holes) {
      Path hole = to_path(ring);
      if (hole.size() < 3) continue;
      if (ClipperLib::Orientation(hole)) ClipperLib::ReversePath(hole);
      paths.push_back(std::move(hole));
    }
  }
  if (paths.empty()) return Region();
  return Region(Impl::execute(ClipperLib::ctUnion, paths, {}));
}

Region Region::union_all(const std::vector<Region>& regions) {
  std::vector<const Region*> parts;
  for (const auto& r : regions) {
    if (!r.empty()) parts.push_back(&r);
  }
  if (parts.empty()) return Region();
  if (parts.size() == 1) return *parts.front();
  if (parts.size() == 2) return parts[0]->united(*parts[1]);
  // Each region winds once around its points (outer contours positive, holes negative), so the
  // points where the sum of the windings is not zero are the union.
  Paths paths;
  for (const auto* r : parts) {
    for (const auto& c : r->impl_->components) {
      paths.push_back(c.outer);
      paths.insert(paths.end(), c.holes.begin(), c.holes.end());
    }
  }
  return Region(Impl::execute(ClipperLib::ctUnion, paths, {}));
}

bool Region::empty() const { return impl_->components.empty(); }

// Regions whose boxes share no area share no area either: their intersection is empty and a
// difference leaves the first, without a sweep; boxes apart (not even touching) unite as both.
Region Region::united(const Region& other) const {
  if (same_as(other) || other.empty() || impl_->equals(*other.impl_)) return *this;
  if (empty()) return other;
  if (boxes_apart(bbox(), other.bbox())) {
    auto impl = std::make_shared<Impl>(*impl_);
    impl->components.insert(impl->components.end(), other.impl_->components.begin(), other.impl_->components.end());
    impl->finish();
    return Region(std::move(impl));
  }
  return Region(Impl::execute(ClipperLib::ctUnion, impl_->paths(), other.impl_->paths()));
}

Region Region::intersected(const Region& other) const {
  if (same_as(other) || impl_->equals(*other.impl_)) return *this;
  if (!boxes_overlap(bbox(), other.bbox())) return Region();
  const GridBox mine = grid_box(*bbox()), theirs = grid_box(*other.bbox());
  if (other.impl_->box_holds(mine)) return *this;
  if (impl_->box_holds(theirs)) return other;
  if (other.impl_->box_in_holes(mine) || impl_->box_in_holes(theirs)) return Region();
  return Region(Impl::execute(ClipperLib::ctIntersection, impl_->paths_near(other.bbox()), other.impl_->paths_near(bbox())));
}

Region Region::minus(const Region& other) const {
  if (same_as(other) || impl_->equals(*other.impl_)) return Region();
  if (other.empty() || !boxes_overlap(bbox(), other.bbox())) return *this;
  const GridBox mine = grid_box(*bbox());
  if (other.impl_->box_holds(mine)) return Region();
  if (other.impl_->box_in_holes(mine)) return *this;
  return Region(Impl::execute(ClipperLib::ctDifference, impl_->paths(), other.impl_->paths_near(bbox())));
}

Region Region::filled() const {
  if (std::all_of(impl_->components.begin(), impl_->components.end(),
                  [](const Impl::Component& c) { return c.holes.empty() && !c.nested; })) {
    return *this;
  }
  auto impl = std::make_shared<Impl>();
  for (const auto& c : impl_->components) {
    if (!c.nested) impl->components.push_back({c.outer, {}, false, {}, {}});
  }
  impl->finish();
  return Region(std::move(impl));
}

Region Region::translated(double dx, double dy) const {
  const cInt sx = to_grid(dx), sy = to_grid(dy);
  auto impl = std::make_shared<Impl>(*impl_);
  auto move = [&](Path& path) {
    for (auto& q : path) q.X += sx, q.Y += sy;
  };
  for (auto& c : impl->components) {
    move(c.outer);
    for (auto& h : c.holes) move(h);
  }
  impl->finish();
  return Region(std::move(impl));
}

double Region::area() const { return impl_->area; }

std::size_t Region::vertex_count() const { return impl_->vertices; }


std::optional<Box2> Region::bbox() const { return impl_->box; }

bool Region::contains(Point2 p) const {
  const IntPoint q(to_grid(p.x), to_grid(p.y));
  if (impl_->tiled()) {
    // One tile whose box holds the point decides: the region there is its contours.
    for (const auto& tile : impl_->tiles()) {
      if (!tile.box.touches({q.X, q.Y, q.X, q.Y})) continue;
      int winding = 0;
      work_done += count_vertices(tile.paths);
      for (const auto& path : tile.paths) {
        const int side = ClipperLib::PointInPolygon(q, path);
        if (side == -1) return true;  // on the boundary
        if (side == 1) winding += ClipperLib::Orientation(path) ? 1 : -1;
      }
      return winding > 0;
    }
    return false;
  }
  for (const auto& c : impl_->components) {
    work_done += c.outer.size();
    if (ClipperLib::PointInPolygon(q, c.outer) == 0) continue;  // outside (1 inside, -1 on it)
    const bool in_hole = std::any_of(c.holes.begin(), c.holes.end(),
                                     [&](const Path& h) { return ClipperLib::PointInPolygon(q, h) == 1; });
    if (!in_hole) return true;
  }
  return false;
}

std::vector<Region> Region::components() const {
  std::vector<Region> out;
  for (const auto& c : impl_->components) {
    auto impl = std::make_shared<Impl>();
    impl->components.push_back({c.outer, c.holes, false, {}, {}});
    impl->finish();
    out.push_back(Region(std::move(impl)));
  }
  return out;
}

std::vector<PolygonWithHoles> Region::polygons() const {
  std::vector<PolygonWithHoles> out;
  for (const auto& c : impl_->components) {
    PolygonWithHoles p;
    p.outer = to_ring(c.outer);
    for (const auto& h : c.holes) p.holes.push_back(to_ring(h));
    out.push_back(std::move(p));
  }
  return out;
}

std::uint64_t region_work() { return work_done; }

bool boxes_apart(const std::optional<Box2>& a, const std::optional<Box2>& b) {
  return a && b && (a->xmax < b->xmin || b->xmax < a->xmin || a->ymax < b->ymin || b->ymax < a->ymin);
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
