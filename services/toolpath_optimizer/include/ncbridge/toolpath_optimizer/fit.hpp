#pragma once
// Fitting a run of moves (a polyline with the same feed, kind and extrusion class throughout)
// with fewer, longer moves: lines that merge collinear moves, arcs (plane and helical, up to a
// full circle), and short moves folded into their neighbours.
//
// The band is guaranteed by construction. Each fitted move starts and ends at input vertices.
// For each input vertex the fitter picks a point of the fitted move, in order along it; between
// two vertices the input segment and the fitted piece are compared point for point (the same
// fraction of each), which bounds the distance both ways: every input point is within the
// tolerance of the output and every output point within the tolerance of the input. For a line
// the bound is the larger vertex distance; for an arc of radius r it adds
// r * sqrt((1 - cos a)^2 + (a - sin a)^2), a = half the angle between the two vertices.
// Arc centres are rounded to the resolution they are written with before they are checked.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "ncbridge/toolpath_optimizer/geometry.hpp"
#include "ncbridge/toolpath_optimizer/toolpath.hpp"

namespace ncbridge::toolpath_optimizer {

struct FitOptions {
  double tolerance = 0.025;           // the band, program units
  double margin = 0;                  // taken off the band for what the writer rounds later
  double min_segment = 0;             // moves shorter than this are folded where the band allows
  bool arcs = true;
  bool helical = true;                // arcs whose normal axis moves (linearly with the angle)
  double centre_resolution = 1e-4;    // arc centres are rounded to this (0: not rounded)
  double max_radius = 10000;          // program units; larger arcs stay lines
  double min_arc_radius = 0;          // program units; smaller arcs stay lines
  double extrusion_rate_variance = 0.05;  // filament per length may vary this much inside a move
  canonical::Plane plane = canonical::Plane::XY;
};

struct FitVertex {
  Vec3 p;
  double e = 0;       // filament fed from the run's start up to this vertex
  double along = 0;   // path length from the run's start up to this vertex
};

struct FittedMove {
  std::size_t first = 0, last = 0;  // vertex indices it spans
  bool arc = false;
  ArcGeometry geometry;             // when arc
};

struct FitStats {
  std::uint64_t arcs = 0;
  std::uint64_t lines_merged = 0;   // output lines that stand for more than one input move
  std::uint64_t folded = 0;         // short moves folded into a neighbour
};

// What the arc fitter keeps between candidates: the vertices from one start on, in the plane
// relative to it (grown as candidates grow), and per-vertex buffers. Reused from run to run, so
// that a long file is fitted without allocating per candidate.
struct FitWorkspace {
  std::vector<PlanePoint> points;
  std::size_t start = 0;       // the vertex `points` are relative to
  bool valid = false;          // points belong to the current vertices and start
  std::vector<double> rho, steps;
};

// Fits vertices[0..n) into moves appended to `out` (in order, covering every segment once).
void fit_polyline(std::span<const FitVertex> vertices, const FitOptions& options, std::vector<FittedMove>& out,
                  FitStats& stats, FitWorkspace& workspace);
void fit_polyline(std::span<const FitVertex> vertices, const FitOptions& options, std::vector<FittedMove>& out,
                  FitStats& stats);

// The pieces fit_polyline is made of, for tests.
bool line_fits(std::span<const FitVertex> v, std::size_t first, std::size_t last, double tolerance);
bool arc_fits(std::span<const FitVertex> v, std::size_t first, std::size_t last, const FitOptions& options,
              ArcGeometry& geometry);
// The same with the caller's workspace (its points are reused while `first` stays the same).
bool arc_fits(std::span<const FitVertex> v, std::size_t first, std::size_t last, const FitOptions& options,
              ArcGeometry& geometry, FitWorkspace& workspace);
// Folds fitted moves shorter than options.min_segment into the move before or after where one
// line or arc takes both within the band. Works on out[begin..].
void fold_short_moves(std::span<const FitVertex> v, const FitOptions& options, std::vector<FittedMove>& out,
                      std::size_t begin, FitStats& stats);

}  // namespace ncbridge::toolpath_optimizer
