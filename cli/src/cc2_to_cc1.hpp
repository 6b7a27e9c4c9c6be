#pragma once
// `ncbridge convert PART_CC2.stp --level cc1`: a CC2 model's workingsteps into explicit
// toolpaths (services/toolpath_generator), the CC1 model written like any other.
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/setup/stock.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::cli {

// Whether the model holds work only a generator can turn into toolpaths: a 2.5D milling
// operation, or a feature other than TOOLPATH_FEATURE and ROUND_HOLE (a CC1 model has none).
bool needs_toolpaths(const stepnc::Project& project);

// The CC1 model of a CC2 one; `stock` is used when the model has no rawpiece. Warnings (the
// generator's choices) are appended. Throws InputError naming `source` and the workingstep.
stepnc::Project generate_cc1(const stepnc::Project& cc2, const std::optional<setup::Stock>& stock, const std::string& source,
                             std::vector<std::string>& warnings);

}  // namespace ncbridge::cli
