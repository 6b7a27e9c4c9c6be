#pragma once
// Phase 1, cutter-location analysis: the workingsteps' feed moves cut into passes (a pass ends
// at every rapid), drilling passes told from milling ones, and milling passes sliced into
// layers (one cutting level each, the plunges and ramps that reach it included).
#include <cstddef>
#include <functional>
#include <vector>

#include "ncbridge/feature_recognizer/toolpath.hpp"
#include "region.hpp"

namespace ncbridge::feature_recognizer {

// Feed moves of one workingstep between two rapids, arcs as chords within the tolerance.
struct CuttingPass {
  std::size_t workingstep = 0;  // the first; a pass runs on across workingsteps with no rapid between
  // The workingstep of each point, as runs: (first point, workingstep), ascending.
  std::vector<std::pair<std::size_t, std::size_t>> workingstep_runs;
  std::size_t sequence = 0;     // position among all passes of the program
  std::vector<Point3> points;   // the polyline, first point = where the feed motion starts
  double xy_length = 0;
  double z_min = 0, z_max = 0;
  bool z_only() const;          // a plunge: no motion in XY beyond 1 µm
  // The workingsteps of the points [first, last), ascending, each once.
  std::vector<std::size_t> workingsteps_of(std::size_t first, std::size_t last) const;
};

// One cutting level of one tool: the paths cut at that level, in order.
struct Layer {
  std::vector<std::size_t> workingsteps;  // ascending, unique
  std::size_t sequence = 0;                // of the first pass cutting at this layer
  setup::Tool tool;
  double z = 0;                            // the cutting level (lowest tool tip z)
  double z_top = 0;                        // highest z of its cutting moves (ramp entries)
  std::vector<std::vector<Point3>> paths;  // one per pass piece
  double feed = 0, spindle_rpm = 0;
  bool freeform = false;                   // x, y and z vary together (3D surface machining)
  bool coarse = false;                     // beyond the work limit: no swept area (its extent stands for it)
  Region area;                             // the tool's swept region (filled in by the caller)
  Box2 extent;                             // bounding box of the swept region
  std::vector<std::vector<Point2>> xy_paths() const;
};

struct DrillPass {
  std::size_t workingstep = 0;
  std::size_t sequence = 0;
  setup::Tool tool;
  Point2 at;
  double z_bottom = 0, z_top = 0;
  std::optional<canonical::CycleTag> cycle;
  double feed = 0, spindle_rpm = 0;
};

struct CutterLocationAnalysis {
  std::vector<DrillPass> drill_passes;
  std::vector<Layer> layers;  // milling layers in machining order
};

// `checkpoint` (if set) is called after each cutting pass.
CutterLocationAnalysis analyse_cutter_locations(const std::vector<ToolpathWorkingstep>& workingsteps,
                                                double chord_tolerance, const std::function<void()>& checkpoint = {});

// True for tools that only cut along their axis (drills, reamers, taps, boring bars).
bool is_hole_making_tool(setup::ToolType type);

}  // namespace ncbridge::feature_recognizer
