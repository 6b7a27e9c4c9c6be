#include "cc2_to_cc1.hpp"

#include <type_traits>

#include "ncbridge/toolpath_generator/toolpath_generator.hpp"

namespace ncbridge::cli {

bool needs_toolpaths(const stepnc::Project& project) {
  for (const auto& e : project.main_workplan.its_elements) {
    const auto* ws = std::get_if<stepnc::MachiningWorkingstep>(&e);
    if (!ws || ws->its_feature.index >= project.features.size() || ws->its_operation.index >= project.operations.size()) continue;
    const auto& f = project.feature(ws->its_feature);
    if (!std::holds_alternative<stepnc::ToolpathFeature>(f) && !std::holds_alternative<stepnc::RoundHole>(f)) return true;
    const bool milling = std::visit(
        [](const auto& o) { return std::is_base_of_v<stepnc::Two5DMillingOperation, std::decay_t<decltype(o)>>; },
        project.operation(ws->its_operation));
    if (milling) return true;
  }
  return false;
}

stepnc::Project generate_cc1(const stepnc::Project& cc2, const std::optional<setup::Stock>& stock, const std::string& source,
                             std::vector<std::string>& warnings) {
  toolpath_generator::Options options;
  options.stock = stock;
  options.source_name = source;
  auto generated = toolpath_generator::generate_toolpaths(cc2, options);
  warnings.insert(warnings.end(), generated.warnings.begin(), generated.warnings.end());
  return std::move(generated.cc1);
}

}  // namespace ncbridge::cli
