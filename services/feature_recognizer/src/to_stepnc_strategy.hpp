#pragma once
// The directions a 2.5D milling strategy names (ISO 14649-11 UNIDIRECTIONAL / BIDIRECTIONAL
// feed_direction and stepover_direction, CONTOUR_* rotation_direction), read from an
// operation's cutter-location curves at its deepest cutting level.
#include <optional>
#include <vector>

#include "ncbridge/stepnc/geometry.hpp"
#include "ncbridge/stepnc/operations.hpp"

namespace ncbridge::feature_recognizer {

struct PathDirections {
  std::optional<stepnc::Direction> feed_direction;  // of the first straight pass, program frame
  std::optional<stepnc::LeftOrRight> stepover_direction;  // where the next pass lies, seen along it
  std::optional<stepnc::RotDirection> rotation;     // sense of the path about +Z (signed area)
};

// `passes`: the operation mills parallel passes; the contour a pocketing ends them with (its
// finishing pass, coming back to where it began) does not tell their direction.
PathDirections analyse_path_directions(const std::vector<const stepnc::CompositeCurve*>& cutting_curves, bool passes = false);

// The points of a curve in order (arcs sampled every 10 degrees, helices with linear z).
std::vector<stepnc::CartesianPoint> curve_points(const stepnc::CompositeCurve& curve);

}  // namespace ncbridge::feature_recognizer
