#pragma once
// Scoring a `plan` report's features against a CAM part's truth.json with the tolerances of
// issue 13: same type, centre within 0.05 mm, dimensions within 0.05 mm, top and bottom exact
// (1e-6 mm). Each truth feature is matched once, to the first report feature that agrees.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ncbridge::testing {

struct TruthScore {
  int truth = 0, reported = 0, matched = 0;
  std::vector<std::string> unmatched;  // truth ids with what was nearest, for the failure message
  double f1() const { return truth + reported == 0 ? 1.0 : 2.0 * matched / (truth + reported); }
};

TruthScore score_against_truth(const nlohmann::json& report_features, const nlohmann::json& truth_features);

}  // namespace ncbridge::testing
