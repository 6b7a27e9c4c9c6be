#include <algorithm>
#include <cmath>

#include "operation_plan.hpp"

namespace ncbridge::process_planner {

double axial_limit(const setup::Tool& tool, double fraction_of_diameter) {
  double limit = fraction_of_diameter * tool.diameter;
  if (tool.flute_length > 0) limit = std::min(limit, tool.flute_length);
  return std::max(limit, 0.01);
}

std::string feature_text(const part_reader::Feature& f, const std::string& id) {
  return f.source.empty() ? id : id + " (" + f.source + ")";
}

}  // namespace ncbridge::process_planner
