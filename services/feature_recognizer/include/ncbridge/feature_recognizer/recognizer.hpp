#pragma once
// The feature recogniser (CC1 workingsteps -> CC2 features), after Xú, Anwer, Lavernhe (2014):
// phase 1 by tool type and cutter-location analysis, phase 2 by the cutting area and the milling
// strategy compared with the stock and the material left by earlier workingsteps.
// docs/recognition.md describes the rules and tolerances.
#include <functional>
#include <vector>

#include "ncbridge/feature_recognizer/feature.hpp"
#include "ncbridge/feature_recognizer/toolpath.hpp"
#include "ncbridge/setup/stock.hpp"

namespace ncbridge::feature_recognizer {

struct Options {
  // Largest distance between a true swept boundary (lines, arcs, the tool's circle) and the
  // polygons the cutting areas are computed with.
  double chord_tolerance = 0.01;
  // A later layer or operation whose depth goes at most this far below a feature's floor is
  // still that feature (finishing allowance), not a new, deeper feature.
  double finishing_allowance = 1.0;
  // The bound on exact geometric work (docs/recognition.md, "Bounded cost"): each stage that
  // makes or compares cutting areas may spend work_base + work_per_point × (toolpath points)
  // units (one unit: a vertex handed to or made by a Boolean operation, about 0.2 µs); what a
  // stage meets beyond that is treated coarsely and the features made of it are marked
  // approximate. Real programs spend under 10 per point; 0 work_per_point: no bound.
  double work_per_point = 40;
  double work_base = 5e6;
  // Called between cutting passes, layers, features and holes; it may throw to stop recognition
  // (a service's job time limit, `convert --max-seconds`). Empty: never called.
  std::function<void()> checkpoint;
};

// Recognises the features cut by `workingsteps` from `stock`. Throws ncbridge::InputError for
// input it cannot use (a milling workingstep whose tool has no diameter, a non-finite
// coordinate), naming the source line of the offending move where known.
std::vector<RecognizedFeature> recognize(const std::vector<ToolpathWorkingstep>& workingsteps,
                                         const setup::Stock& stock, const Options& options = {});

}  // namespace ncbridge::feature_recognizer
