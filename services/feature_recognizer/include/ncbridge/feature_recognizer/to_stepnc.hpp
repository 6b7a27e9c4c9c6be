#pragma once
// Recognised features into the ISO 14649 model (CC2): the features the recogniser found in a
// CC1 project become PLANAR_FACE, ROUND_HOLE, CLOSED_POCKET, OPEN_POCKET, SLOT, STEP,
// GENERAL_OUTSIDE_PROFILE and REGION features of a new project, and the CC1 workingsteps that
// cut each of them become one MACHINING_WORKINGSTEP per recognised operation (plane, side or
// bottom-and-side milling with its strategy and depths; the drilling family), keeping the CC1
// cutter-location toolpaths in the operation's its_toolpath. CC1 workingsteps no feature claims
// stay as they were (TOOLPATH_FEATURE with FREEFORM_OPERATION), so nothing of the CC1 file is
// lost. The mapping rules are in docs/cc2.md.
#include <string>
#include <vector>

#include "ncbridge/feature_recognizer/feature.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::feature_recognizer {

struct Cc2Project {
  stepnc::Project project;
  // The CC2 feature id of each recognised feature (same order as the input).
  std::vector<std::string> feature_ids;
  // The CC2 MACHINING_WORKINGSTEP id of each recognised operation ("" when it got none).
  std::vector<std::vector<std::string>> workingstep_ids;
  // What could not be carried over exactly (e.g. an operation that owns no workingstep).
  std::vector<std::string> warnings;
};

// `features` must be what recognize() returned for workingsteps_from_cc1(cc1): their operations'
// workingstep indices are positions among cc1's machining workingsteps.
Cc2Project cc2_from_cc1(const stepnc::Project& cc1, const std::vector<RecognizedFeature>& features);

// The ids cc2_from_cc1 gives: "PLANAR FACE1", "HOLE1 D=22MM", "POCKET1", "OPEN POCKET1",
// "SLOT1", "STEP1", "PROFILE1", "REGION1", numbered per kind in order.
std::vector<std::string> cc2_feature_ids(const std::vector<RecognizedFeature>& features);

}  // namespace ncbridge::feature_recognizer
