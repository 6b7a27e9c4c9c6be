// The fitter: lines, arcs, helices, full circles, folding, and the band held on random runs as
// the deviation checker measures it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ncbridge/toolpath_optimizer/deviation_checker.hpp"
#include "ncbridge/toolpath_optimizer/fit.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"

namespace ncbridge::toolpath_optimizer {
namespace {

std::vector<FitVertex> vertices(const std::vector<Vec3>& points, double e_per_mm = 0) {
  std::vector<FitVertex> v;
  for (const Vec3& p : points) {
    FitVertex f{p, 0, 0};
    if (!v.empty()) {
      const double l = distance(v.back().p, p);
      f.along = v.back().along + l;
      f.e = v.back().e + e_per_mm * l;
    }
    v.push_back(f);
  }
  return v;
}

std::vector<Vec3> polygon(Vec3 centre, double r, double from, double to, int segments, double dz = 0) {
  std::vector<Vec3> p;
  for (int i = 0; i <= segments; ++i) {
    const double a = from + (to - from) * i / segments;
    p.push_back({centre.x + r * std::cos(a), centre.y + r * std::sin(a), centre.z + dz * i / segments});
  }
  return p;
}

std::vector<FittedMove> fit(const std::vector<FitVertex>& v, const FitOptions& o) {
  std::vector<FittedMove> out;
  FitStats stats;
  fit_polyline(v, o, out, stats);
  return out;
}

// The fitted moves as path pieces, and the checker's verdict against the input polyline.
DeviationReport measure(const std::vector<FitVertex>& v, const std::vector<FittedMove>& moves, double tol) {
  std::vector<PathPiece> in, out;
  for (std::size_t i = 1; i < v.size(); ++i) {
    PathPiece p;
    p.start = v[i - 1].p;
    p.end = v[i].p;
    p.extrusion = v[i].e - v[i - 1].e;
    in.push_back(p);
  }
  for (const auto& m : moves) {
    PathPiece p;
    p.line = static_cast<std::uint32_t>(out.size() + 1);
    p.kind = m.arc ? MotionKind::Arc : MotionKind::Line;
    p.start = v[m.first].p;
    p.end = v[m.last].p;
    p.arc = m.geometry;
    p.extrusion = v[m.last].e - v[m.first].e;
    out.push_back(p);
  }
  DeviationOptions o;
  o.tolerance = tol;
  return check_deviation(in, out, o);
}

TEST(Fit, CollinearMovesBecomeOneLine) {
  std::vector<Vec3> p;
  for (int i = 0; i <= 200; ++i) p.push_back({i * 0.5, 0.01 * std::sin(i * 1.7), 0.2});
  const auto v = vertices(p, 0.05);
  FitOptions o;
  const auto moves = fit(v, o);
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_FALSE(moves[0].arc);
  EXPECT_TRUE(measure(v, moves, o.tolerance).passed(o.tolerance));
  // The same at a band narrower than the wiggle: not one line any more, still within the band.
  o.tolerance = 0.005;
  const auto tight = fit(v, o);
  EXPECT_GT(tight.size(), 1u);
  EXPECT_TRUE(measure(v, tight, o.tolerance).passed(o.tolerance));
}

TEST(Fit, APolygonalArcBecomesOneArcInEitherDirection) {
  FitOptions o;
  o.centre_resolution = 0;
  for (bool ccw : {true, false}) {
    const auto v = vertices(polygon({50, 50, 0.3}, 20, 0.3, ccw ? 2.1 : -1.5, 60), 0.04);
    const auto moves = fit(v, o);
    ASSERT_EQ(moves.size(), 1u);
    ASSERT_TRUE(moves[0].arc);
    EXPECT_EQ(moves[0].geometry.ccw, ccw);
    EXPECT_NEAR(moves[0].geometry.first_centre, 50, 0.01);
    EXPECT_NEAR(moves[0].geometry.second_centre, 50, 0.01);
    EXPECT_TRUE(measure(v, moves, o.tolerance).passed(o.tolerance));
  }
}

TEST(Fit, AClosedPolygonBecomesAFullCircle) {
  FitOptions o;
  const auto v = vertices(polygon({10, 20, 1}, 8, 0, 2 * kPi, 90), 0.03);
  const auto moves = fit(v, o);
  ASSERT_EQ(moves.size(), 1u);
  ASSERT_TRUE(moves[0].arc);
  EXPECT_EQ(moves[0].first, 0u);
  EXPECT_EQ(moves[0].last, v.size() - 1);
  const auto d = measure(v, moves, o.tolerance);
  EXPECT_TRUE(d.passed(o.tolerance)) << d.largest();
}

TEST(Fit, AHelixIsOneHelicalArcUnlessHelicesAreOff) {
  FitOptions o;
  const auto v = vertices(polygon({0, 0, 5}, 15, 0, 4.0, 80, 0.8));
  auto moves = fit(v, o);
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_TRUE(moves[0].arc);
  EXPECT_TRUE(measure(v, moves, o.tolerance).passed(o.tolerance));
  o.helical = false;
  moves = fit(v, o);
  for (const auto& m : moves) EXPECT_FALSE(m.arc);
  EXPECT_TRUE(measure(v, moves, o.tolerance).passed(o.tolerance));
}

TEST(Fit, ArcsInTheXzAndYzPlanes) {
  for (auto plane : {canonical::Plane::XZ, canonical::Plane::YZ}) {
    std::vector<Vec3> p;
    for (const Vec3& q : polygon({0, 0, 0}, 12, 0.2, 2.5, 50)) p.push_back(from_plane({q.x, q.y, 3.0}, plane));
    FitOptions o;
    o.plane = plane;
    const auto v = vertices(p);
    const auto moves = fit(v, o);
    ASSERT_EQ(moves.size(), 1u);
    EXPECT_TRUE(moves[0].arc);
    EXPECT_EQ(moves[0].geometry.plane, plane);
    EXPECT_TRUE(measure(v, moves, o.tolerance).passed(o.tolerance));
  }
}

TEST(Fit, ExtrusionPerLengthNeverChangesInsideAMove) {
  // The same arc, the second half extruding 20 % more per mm: two moves, split where it changes.
  auto p = polygon({0, 0, 0}, 20, 0, 2, 40);
  std::vector<FitVertex> v = vertices(p);
  for (std::size_t i = 1; i < v.size(); ++i) {
    const double rate = i <= 20 ? 0.05 : 0.06;
    v[i].e = v[i - 1].e + rate * (v[i].along - v[i - 1].along);
  }
  FitOptions o;
  const auto moves = fit(v, o);
  ASSERT_EQ(moves.size(), 2u);
  EXPECT_EQ(moves[0].last, 20u);
}

TEST(Fit, ShortMovesAreFoldedWhereTheBandAllows) {
  // Moves as a search that stopped early might leave them: a 0.1 mm move between two lines, the
  // first of which can take it within the band, and one that no neighbour can take.
  std::vector<Vec3> p = {{0, 0, 0}, {10, 0, 0}, {10.1, 0.001, 0}, {20, 0.2, 0}, {20.05, 0.5, 0}, {30, 0.5, 0}};
  const auto v = vertices(p);
  FitOptions o;
  o.min_segment = 0.2;
  std::vector<FittedMove> moves = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}};
  FitStats stats;
  fold_short_moves(v, o, moves, 0, stats);
  ASSERT_EQ(moves.size(), 4u);
  EXPECT_EQ(stats.folded, 1u);
  EXPECT_EQ(moves[0].first, 0u);
  EXPECT_EQ(moves[0].last, 2u);
  EXPECT_EQ(moves[2].last - moves[2].first, 1u);  // the 0.3 mm jog: 0.3 off any neighbour
  EXPECT_TRUE(measure(v, moves, o.tolerance).passed(o.tolerance));
  // Without --min-segment nothing is folded.
  o.min_segment = 0;
  moves = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}};
  fold_short_moves(v, o, moves, 0, stats);
  EXPECT_EQ(moves.size(), 5u);
}

TEST(Fit, ANoisyPolygonIsOneArcWhenItsPiecesStayNearTheirSegments) {
  // 56 segments over a quarter circle of radius 20 (sagitta 0.002 mm), every other vertex 0.004
  // mm off the circle, out and in. Compared point for point (an arc piece and its segment at
  // equal fractions) the arc would be off by up to sagitta + 0.004 > 0.005; measured as the
  // distance of the arc piece to its segment (about sagitta + 0.002 at most) it stays inside
  // 0.005, and the independent checker agrees.
  std::vector<Vec3> p;
  for (int i = 0; i <= 56; ++i) {
    const double a = kPi / 2 * i / 56, r = 20 + 0.004 * std::sin(i * kPi / 2);
    p.push_back({r * std::cos(a), r * std::sin(a), 0.2});
  }
  const auto v = vertices(p, 0.05);
  FitOptions o;
  o.tolerance = 0.005;
  const auto moves = fit(v, o);
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_TRUE(moves[0].arc);
  const auto d = measure(v, moves, o.tolerance);
  EXPECT_TRUE(d.passed(o.tolerance)) << d.largest();
  EXPECT_GT(d.largest(), 0.0039);
}

TEST(Fit, RandomRunsStayInTheBand) {
  // Noisy circles, spirals, corners and straight stretches at several bands: whatever the fitter
  // makes, the independent checker finds it within the band.
  std::mt19937 random(14);
  std::uniform_real_distribution<double> u(0, 1);
  int arcs = 0;
  FitWorkspace shared;  // one workspace through all runs, as the optimizer keeps it
  for (int trial = 0; trial < 300; ++trial) {
    const double tol = trial % 2 ? 0.025 : 0.005;
    std::vector<Vec3> p;
    Vec3 at{u(random) * 100, u(random) * 100, 0.2};
    const int pieces = 1 + trial % 4;
    for (int k = 0; k < pieces; ++k) {
      const double r = 1 + u(random) * 40;
      const double a0 = u(random) * 6.28, sweep = (u(random) - 0.5) * 7;
      const int n = 3 + static_cast<int>(u(random) * 80);
      const double noise = tol * u(random) * 0.8, dz = trial % 5 == 0 ? 0.3 * u(random) : 0;
      const Vec3 centre{at.x - r * std::cos(a0), at.y - r * std::sin(a0), at.z};
      for (int i = 0; i <= n; ++i) {
        const double a = a0 + sweep * i / n;
        const double rr = k % 3 == 2 ? r + 5 * i / n : r;  // a spiral now and then
        p.push_back({centre.x + rr * std::cos(a) + noise * (u(random) - 0.5), centre.y + rr * std::sin(a) + noise * (u(random) - 0.5),
                     centre.z + dz * i / n});
      }
      at = p.back();
    }
    const auto v = vertices(p, trial % 3 ? 0.04 : 0.0);
    FitOptions o;
    o.tolerance = tol;
    o.min_segment = trial % 7 == 0 ? 0.3 : 0;
    const auto moves = fit(v, o);
    std::vector<FittedMove> again;
    FitStats stats;
    fit_polyline(v, o, again, stats, shared);
    ASSERT_EQ(again.size(), moves.size()) << "trial " << trial << ": a reused workspace fits otherwise";
    for (std::size_t i = 0; i < moves.size(); ++i) {
      EXPECT_EQ(again[i].last, moves[i].last);
      EXPECT_EQ(again[i].arc, moves[i].arc);
      EXPECT_EQ(again[i].geometry.first_centre, moves[i].geometry.first_centre);
    }
    for (const auto& m : moves) arcs += m.arc;
    const auto d = measure(v, moves, tol);
    ASSERT_TRUE(d.passed(tol)) << "trial " << trial << ": " << d.input_to_output << " / " << d.output_to_input << " "
                               << (d.problems.empty() ? "" : d.problems.front());
  }
  EXPECT_GT(arcs, 100);
}

}  // namespace
}  // namespace ncbridge::toolpath_optimizer
