#pragma once
// Phase 2, the milling strategy of a layer from its cutter-location path: parallel passes
// (unidirectional or bidirectional), a centre line, one contour, nested contours (contour
// parallel), a spiral, a helix or circle, or adaptive (trochoidal) clearing.
#include "cutting_layers.hpp"

namespace ncbridge::feature_recognizer {

struct StrategyAnalysis {
  Strategy strategy = Strategy::None;
  double stepover = 0;          // distance between neighbouring parallel passes or contours
  int closed_loops = 0;         // loops the path closes at the level
  // Circles: the cutting moves go round one centre (arcs, or their chords as CC1 gives a helix),
  // one full turn or more at each radius; links between them are short.
  std::vector<double> circle_radii;  // ascending; empty when the path is not made of circles
  bool helical = false;              // z falls along the circles (hole milling by helix)
  bool helical_entry = false;        // ... only as the entry: flat circles at several radii follow
  bool single_circle = false;        // one radius
  Point2 circle_center;
  double circle_radius = 0;          // the largest
};

StrategyAnalysis analyse_strategy(const Layer& layer);

}  // namespace ncbridge::feature_recognizer
