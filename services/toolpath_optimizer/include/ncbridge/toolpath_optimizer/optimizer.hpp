#pragma once
// The toolpath_optimizer stage: an element stream in, the same stream with runs of moves
// replaced by fewer moves out (fit.hpp). A run is a sequence of consecutive motions that can be
// fitted together: straight (G0 or G1, not both), from a known position, same feed, units and
// plane, all extruding or all travelling or all retracting on the way (a wipe), no rotary axis
// moving. Comment and blank lines inside a run do not end it: they keep their order and come
// right after the fitted move that spans their place. Anything else (a command line, a
// canonical call, an arc or a filament-only move of the input, a motion kept as written) ends
// the run and passes through in place. Memory holds one run (at most max_run motions; a longer
// run is cut there).
#include <cstdint>
#include <utility>
#include <vector>

#include "ncbridge/toolpath_optimizer/fit.hpp"
#include "ncbridge/toolpath_optimizer/toolpath.hpp"

namespace ncbridge::toolpath_optimizer {

struct OptimizerOptions {
  double tolerance_mm = 0.025;
  double min_segment_mm = 0;
  double margin_mm = 0;              // kept free of the band for rounding the writer does later
  bool arcs = true;
  bool helical = true;
  bool travel_arcs = true;           // arcs for moves that do not extrude (G1 without E)
  bool xy_arcs_only = false;         // no arcs fitted in the XZ and YZ planes
  double max_radius_mm = 10000;
  double min_arc_radius_mm = 0;
  double extrusion_rate_variance = 0.05;
  // Arc centres are written with this many decimals (in mm; one more in inches); -1: one more
  // than the run's coordinates (printer files; CNC output states the writer's).
  int centre_decimals = -1;
  std::size_t max_run = 50000;
  // An input arc whose end is not quite on its circle (a spiral by a hair, which some controls
  // accept and some writers refuse) gets its centre moved onto the chord's bisector, where that
  // moves its path by at most half the band (measured along the arc).
  bool true_arcs = false;
};

struct OptimizerStats {
  std::uint64_t motions_in = 0;
  std::uint64_t motions_out = 0;
  std::uint64_t arcs = 0;
  std::uint64_t lines_merged = 0;
  std::uint64_t folded = 0;
  std::uint64_t runs = 0;
  std::uint64_t arcs_recentred = 0;
};

class Optimizer final : public ElementSink {
 public:
  Optimizer(const OptimizerOptions& options, ElementSink& out);
  void element(Element&& e) override;
  void end() override;
  const OptimizerStats& stats() const { return stats_; }

 private:
  bool fittable(const Motion& m) const;
  void true_arc(Motion& m);
  bool continues_run(const Motion& m) const;
  void flush();
  void emit(Element&& e);

  OptimizerOptions options_;
  ElementSink& out_;
  OptimizerStats stats_;
  std::vector<Motion> run_;
  std::vector<FitVertex> vertices_;
  std::vector<FittedMove> fitted_;
  FitWorkspace workspace_;
  std::vector<std::pair<std::size_t, Element>> riders_;  // comments inside the run, after motion n
};

}  // namespace ncbridge::toolpath_optimizer
