#pragma once
// `ncbridge convert --level cc2`: recognition on a CC1 project and what the command writes from
// it (the CC2 project, the report's `features` array in the shape of docs/formats/report.md).
#include <nlohmann/json.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/feature_recognizer/feature.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::cli {

struct Cc2Output {
  setup::Stock stock;                                       // what recognition compared with
  std::vector<feature_recognizer::RecognizedFeature> features;
  std::vector<std::string> feature_ids;                     // CC2 ids, same order
  std::vector<std::vector<std::string>> workingstep_ids;    // per feature, per operation
  stepnc::Project project;                                  // the CC2 workplan
  std::vector<std::string> warnings;
};

// Recognises the features of `cc1` against its rawpiece block (or `stock` when the project has
// none: a CC1 file without a rawpiece needs --stock). Throws InputError when neither exists.
// `checkpoint` (if set) is the recogniser's (feature_recognizer::Options): it may throw to stop.
Cc2Output build_cc2(const stepnc::Project& cc1, const std::optional<setup::Stock>& stock, const std::string& source,
                    const std::function<void()>& checkpoint = {});

// The report's `features` array (docs/formats/report.md).
nlohmann::ordered_json cc2_features_json(const Cc2Output& out);

}  // namespace ncbridge::cli
