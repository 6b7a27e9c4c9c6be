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
  bool single_circle = false;   // every cutting move is an arc (helix) about one centre, one radius
  Point2 circle_center;         // single_circle: its centre and path radius
  double circle_radius = 0;
};

StrategyAnalysis analyse_strategy(const Layer& layer);

}  // namespace ncbridge::feature_recognizer
