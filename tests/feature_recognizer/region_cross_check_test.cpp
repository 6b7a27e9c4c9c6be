// Region (Clipper, integer grid) against the exact union (CGAL, exact constructions) on real
// swept areas (the recogniser's own swept_area, made of convex pieces united in a tree, against
// the exact union of one stadium per segment), and the shortcuts of region.cpp (tiles of large regions, box tests, equal
// regions) against the full operations they replace. Bound: each operation moves a vertex by
// at most half a grid diagonal, so areas agree within perimeter * kGrid per operation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "box_index.hpp"
#include "exact_union.hpp"
#include "region.hpp"
#include "swept_area.hpp"

namespace fr = ncbridge::feature_recognizer;

namespace {

constexpr double kTol = 0.01;

double perimeter(const fr::Region& r) {
  double p = 0;
  for (const auto& pwh : r.polygons()) {
    auto ring_length = [](const fr::Ring& ring) {
      double l = 0;
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const auto& a = ring[i];
        const auto& b = ring[(i + 1) % ring.size()];
        l += std::hypot(b.x - a.x, b.y - a.y);
      }
      return l;
    };
    p += ring_length(pwh.outer);
    for (const auto& h : pwh.holes) p += ring_length(h);
  }
  return p;
}

// Area agreement allowed after `operations` chained operations.
double bound(const fr::Region& r, int operations) { return operations * perimeter(r) * fr::kGrid + 1e-9; }

std::vector<fr::Ring> stadiums(const std::vector<std::vector<fr::Point2>>& paths, double radius) {
  std::vector<fr::Ring> out;
  for (const auto& path : paths) {
    for (std::size_t i = 1; i < path.size(); ++i) out.push_back(fr::stadium(path[i - 1], path[i], radius, kTol));
  }
  return out;
}

// A contour-parallel pocket layer (three loops) entered at `entry`, as CAM posts them.
std::vector<fr::Point2> pocket_path(fr::Point2 c, fr::Point2 entry) {
  std::vector<fr::Point2> path{entry, c};
  for (int loop = 1; loop <= 3; ++loop) {
    const double hx = 10.0 * loop / 3, hy = 5.0 * loop / 3;
    for (const auto& p : {fr::Point2{c.x + hx, c.y - hy}, fr::Point2{c.x + hx, c.y + hy}, fr::Point2{c.x - hx, c.y + hy},
                          fr::Point2{c.x - hx, c.y - hy}, fr::Point2{c.x + hx, c.y - hy}}) {
      path.push_back(p);
    }
  }
  return path;
}

// A zigzag face pass over w x h with a tool of radius r and stepover s.
std::vector<fr::Point2> zigzag(double w, double h, double s) {
  std::vector<fr::Point2> path;
  bool up = true;
  for (double x = 0; x <= w + 1e-9; x += s) {
    path.push_back({x, up ? -5.0 : h + 5});
    path.push_back({x, up ? h + 5 : -5.0});
    up = !up;
  }
  return path;
}

// Every point of a fine grid over `box` that lies in exactly one of a and b, ignoring points
// within `margin` of either boundary (sampled by moving the point by `margin` four ways).
int containment_disagreements(const fr::Region& a, const fr::Region& b, const fr::Box2& box, double margin) {
  int bad = 0;
  for (double x = box.xmin + 0.0137; x < box.xmax; x += 0.731) {
    for (double y = box.ymin + 0.0291; y < box.ymax; y += 0.593) {
      if (a.contains({x, y}) == b.contains({x, y})) continue;
      const bool near_boundary = a.contains({x + margin, y}) != a.contains({x - margin, y}) ||
                                 a.contains({x, y + margin}) != a.contains({x, y - margin});
      if (!near_boundary) ++bad;
    }
  }
  return bad;
}

}  // namespace

TEST(RegionCrossCheck, SweptPocketLayerMatchesTheExactUnion) {
  const auto pieces = stadiums({pocket_path({30, 20}, {40, 15})}, 5);
  const auto exact = fr::exact_union(pieces);
  const auto grid = fr::Region::union_of(pieces);
  ASSERT_FALSE(exact.empty());
  EXPECT_NEAR(grid.area(), exact.area(), bound(exact, 2));
  EXPECT_EQ(grid.components().size(), exact.components().size());
  EXPECT_EQ(containment_disagreements(grid, exact, *exact.bbox(), 1e-4), 0);
  EXPECT_EQ(exact.minus(grid).area() + grid.minus(exact).area() < bound(exact, 3), true);
}

TEST(RegionCrossCheck, NestedLoopsWithRidgesMatchTheExactUnion) {
  // Two square loops wider apart than the tool: an outer ring with a hole, in it an island ring
  // with its own hole.
  auto square = [](double h) {
    return std::vector<fr::Point2>{{-h, -h}, {h, -h}, {h, h}, {-h, h}, {-h, -h}};
  };
  const auto pieces = stadiums({square(30), square(12)}, 4);
  const auto exact = fr::exact_union(pieces);
  const auto grid = fr::Region::union_of(pieces);
  EXPECT_NEAR(grid.area(), exact.area(), bound(exact, 2));
  std::size_t holes_exact = 0, holes_grid = 0;
  for (const auto& p : exact.polygons()) holes_exact += p.holes.size();
  for (const auto& p : grid.polygons()) holes_grid += p.holes.size();
  EXPECT_EQ(holes_exact, 2u);
  EXPECT_EQ(holes_grid, holes_exact);
  EXPECT_EQ(grid.components().size(), 2u);
  EXPECT_EQ(containment_disagreements(grid, exact, *exact.bbox(), 1e-4), 0);
  EXPECT_NEAR(grid.filled().area(), exact.filled().area(), bound(exact, 2));
  EXPECT_NEAR(grid.filled().area(), 68.0 * 68.0 - (4 - std::numbers::pi) * 16, 1.0);  // the outer loop's outline
  EXPECT_TRUE(grid.contains({20, 0}) == false && grid.contains({0, 0}) == false && grid.contains({12, 0}));
}

namespace {

// The same point set both ways: areas within the grid bound, the same components and holes, the
// same containment away from the boundary.
void expect_same_region(const fr::Region& grid, const fr::Region& exact) {
  ASSERT_FALSE(exact.empty());
  EXPECT_NEAR(grid.area(), exact.area(), bound(exact, 4));
  EXPECT_LT(exact.minus(grid).area() + grid.minus(exact).area(), bound(exact, 6));
  EXPECT_EQ(grid.components().size(), exact.components().size());
  std::size_t holes_exact = 0, holes_grid = 0;
  for (const auto& p : exact.polygons()) holes_exact += p.holes.size();
  for (const auto& p : grid.polygons()) holes_grid += p.holes.size();
  EXPECT_EQ(holes_grid, holes_exact);
  EXPECT_EQ(containment_disagreements(grid, exact, *exact.bbox(), 1e-4), 0);
}

// Random long strokes across a plate, as the interpreter benchmark's program cuts (many
// crossings at every angle), and trochoidal loops (each loop overlapping its neighbours many
// times): the tree of convex pieces gives the exact union of the stadiums.
std::vector<fr::Point2> random_strokes(unsigned seed, int count) {
  std::vector<fr::Point2> path;
  for (int i = 0; i < count; ++i) {
    seed = seed * 1103515245u + 12345u;
    const double x = static_cast<double>((seed >> 8) % 200000) / 1000.0;
    seed = seed * 1103515245u + 12345u;
    path.push_back({x, static_cast<double>((seed >> 8) % 150000) / 1000.0});
  }
  return path;
}

std::vector<fr::Point2> trochoid(double loop_radius, double advance_per_loop, int loops) {
  std::vector<fr::Point2> path;
  const int per_loop = 48;
  for (int i = 0; i <= loops * per_loop; ++i) {
    const double t = 2 * std::numbers::pi * i / per_loop;
    path.push_back({advance_per_loop * i / per_loop + loop_radius * std::cos(t), loop_radius * std::sin(t)});
  }
  return path;
}

}  // namespace

TEST(RegionCrossCheck, SweptAreasAreTheExactUnionOfTheirStadiums) {
  const std::vector<std::vector<std::vector<fr::Point2>>> cases = {
      {pocket_path({30, 20}, {40, 15})},
      {{{-30, -30}, {30, -30}, {30, 30}, {-30, 30}, {-30, -30}}, {{-12, -12}, {12, -12}, {12, 12}, {-12, 12}, {-12, -12}}},
      {{{0, 0}, {10, 0}, {10, 0.5}, {0, 0.5}}},  // a hairpin: reversals
      {random_strokes(7, 14)},
      {random_strokes(11, 8), random_strokes(13, 8)},
      {trochoid(2.5, 0.8, 12)},
      {zigzag(60, 30, 7)}};
  for (const auto& paths : cases) {
    std::vector<std::vector<fr::Point2>> simplified;
    for (const auto& p : paths) simplified.push_back(fr::simplify_polyline(p, kTol));
    const auto exact = fr::exact_union(stadiums(simplified, 3));
    expect_same_region(fr::swept_area(paths, 3, kTol), exact);
  }
}

TEST(RegionCrossCheck, OperationsKeepTheirIdentities) {
  const auto a = fr::exact_union(stadiums({pocket_path({30, 20}, {30, 20})}, 5));
  const auto b = fr::exact_union(stadiums({pocket_path({37.3, 24.1}, {37.3, 24.1})}, 4));
  const double tol = bound(a, 3) + bound(b, 3);
  // |A ∪ B| + |A ∩ B| = |A| + |B| and |A − B| = |A| − |A ∩ B|.
  EXPECT_NEAR(a.united(b).area() + a.intersected(b).area(), a.area() + b.area(), tol);
  EXPECT_NEAR(a.minus(b).area(), a.area() - a.intersected(b).area(), tol);
  EXPECT_NEAR(fr::overlap_ratio(a, b), a.intersected(b).area() / a.united(b).area(), 1e-9);
  // A region equal to another but made apart is recognised as equal: no arithmetic, no change.
  const auto again = fr::exact_union(stadiums({pocket_path({30, 20}, {30, 20})}, 5));
  EXPECT_FALSE(again.same_as(a));
  EXPECT_DOUBLE_EQ(a.united(again).area(), a.area());
  EXPECT_TRUE(a.minus(again).empty());
}

TEST(RegionCrossCheck, TranslationMovesOnTheGrid) {
  const auto a = fr::exact_union(stadiums({pocket_path({30, 20}, {40, 15})}, 5));
  const auto moved = a.translated(120.5, -60.25);
  EXPECT_NEAR(moved.area(), a.area(), 1e-9);
  EXPECT_NEAR(moved.bbox()->xmin, a.bbox()->xmin + 120.5, fr::kGrid);
  EXPECT_NEAR(moved.bbox()->ymax, a.bbox()->ymax - 60.25, fr::kGrid);
  const auto direct = fr::exact_union(stadiums({pocket_path({150.5, -40.25}, {160.5, -45.25})}, 5));
  EXPECT_NEAR(moved.minus(direct).area() + direct.minus(moved).area(), 0, bound(a, 3));
}

TEST(RegionCrossCheck, LargeRegionsAnswerFromTheirTilesAsFromTheWhole) {
  // A face milled over 2400 x 400 with a 50 mm tool: thousands of boundary vertices, so region.cpp
  // reads it by tiles; small regions meeting it must get what the whole region gives.
  const auto face = fr::exact_union(stadiums({zigzag(2400, 400, 20)}, 25));
  std::size_t vertices = 0;
  for (const auto& p : face.polygons()) vertices += p.outer.size();
  ASSERT_GT(vertices, 2048u);
  for (const fr::Point2 c : {fr::Point2{300, 200}, fr::Point2{-10, 150}, fr::Point2{2400, 420}, fr::Point2{20, -28}}) {
    const auto small = fr::exact_union(stadiums({pocket_path(c, c)}, 5));
    const double tol = bound(small, 3) + 1e-6;
    const double inter = small.intersected(face).area();
    // The union never uses tiles: |S ∩ F| = |S| + |F| − |S ∪ F|.
    EXPECT_NEAR(inter, small.area() + face.area() - small.united(face).area(), tol + bound(face, 2));
    EXPECT_NEAR(small.minus(face).area(), small.area() - inter, tol);
    EXPECT_NEAR(face.intersected(small).area(), inter, tol);
    const fr::Box2 box = *small.bbox();
    for (double x = box.xmin; x < box.xmax; x += 0.77) {
      for (double y = box.ymin; y < box.ymax; y += 0.61) {
        const bool in_face = face.contains({x, y});
        EXPECT_EQ(small.intersected(face).contains({x, y}), in_face && small.contains({x, y})) << x << " " << y;
      }
    }
  }
}

TEST(RegionCrossCheck, BoxShortcutsGiveTheFullOperationsResult) {
  const auto pocket = fr::exact_union(stadiums({pocket_path({50, 40}, {50, 40})}, 5));
  const auto stock = fr::Region::rectangle({0, 0, 100, 80});
  EXPECT_TRUE(pocket.intersected(stock).same_as(pocket));  // inside the rectangle
  EXPECT_TRUE(pocket.minus(stock).empty());
  // A frame around the stock (the band where cuts open to the side) holds the pocket in its
  // convex hole: nothing in common.
  const auto frame = fr::Region::rectangle({-5, -5, 105, 85}).minus(fr::Region::rectangle({1, 1, 99, 79}));
  EXPECT_TRUE(pocket.intersected(frame).empty());
  EXPECT_TRUE(pocket.minus(frame).same_as(pocket));
  // Near the frame's inner edge the full operation runs and finds the overlap.
  const auto edge_pocket = fr::exact_union(stadiums({pocket_path({12, 40}, {12, 40})}, 5));
  EXPECT_GT(edge_pocket.intersected(frame).area(), 0.5);
  EXPECT_NEAR(edge_pocket.intersected(frame).area() + edge_pocket.minus(frame).area(), edge_pocket.area(),
              bound(edge_pocket, 3));
}

TEST(RegionCrossCheck, NonFiniteCoordinatesStayOnTheGrid) {
  const double inf = std::numeric_limits<double>::infinity();
  const auto r = fr::Region::polygon({{0, 0}, {inf, 0}, {0, std::nan("")}});
  EXPECT_TRUE(std::isfinite(r.area()));
}

TEST(BoxIndex, CandidatesHoldEveryOverlappingBoxInOrder) {
  // Boxes of many sizes (some wider than the index files cell by cell), some re-filed larger.
  fr::BoxIndex index(25.0);
  std::vector<fr::Box2> boxes;
  unsigned seed = 12345;
  auto next = [&seed] {
    seed = seed * 1103515245u + 12345u;
    return static_cast<double>((seed >> 8) % 100000) / 100.0;  // 0 .. 1000
  };
  for (std::size_t i = 0; i < 400; ++i) {
    const double x = next(), y = next(), w = i % 50 == 0 ? 800 : next() / 20, h = next() / 20;
    boxes.push_back({x, y, x + w, y + h});
    index.insert(i, boxes.back());
    if (i % 7 == 0) {
      boxes.back().xmax += 40;  // a feature that grew
      index.insert(i, boxes.back());
    }
  }
  for (std::size_t q = 0; q < 200; ++q) {
    const double x = next(), y = next();
    const fr::Box2 query{x, y, x + next() / 10, y + next() / 10};
    const auto found = index.candidates(query);
    EXPECT_TRUE(std::is_sorted(found.begin(), found.end()));
    EXPECT_EQ(std::adjacent_find(found.begin(), found.end()), found.end());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const auto& b = boxes[i];
      const bool touches = b.xmin <= query.xmax && query.xmin <= b.xmax && b.ymin <= query.ymax && query.ymin <= b.ymax;
      if (touches) {
        EXPECT_TRUE(std::binary_search(found.begin(), found.end(), i)) << "box " << i << " query " << q;
      }
    }
  }
  // The latest ids near a box: the highest of the candidates, highest first, at most as many as asked.
  for (std::size_t q = 0; q < 50; ++q) {
    const double x = next(), y = next();
    const fr::Box2 query{x, y, x + next() / 5, y + next() / 5};
    const auto all = index.candidates(query);
    for (std::size_t limit : {std::size_t{0}, std::size_t{1}, std::size_t{5}, std::size_t{1000}}) {
      const auto latest = index.latest(query, limit);
      const std::vector<std::size_t> expected(all.rbegin(), all.rbegin() + static_cast<std::ptrdiff_t>(std::min(limit, all.size())));
      EXPECT_EQ(latest, expected) << "query " << q << " limit " << limit;
    }
  }
  // A point on a cell line finds the boxes on both sides of it.
  fr::BoxIndex lines(10.0);
  lines.insert(0, {0, 0, 10, 10});
  lines.insert(1, {10, 0, 20, 10});
  EXPECT_EQ(lines.candidates({10, 5, 10, 5}).size(), 2u);
}

