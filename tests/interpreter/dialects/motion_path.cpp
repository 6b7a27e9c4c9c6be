#include "motion_path.hpp"

#include <cmath>
#include <cstdlib>

#include "support/canon_listing.hpp"

namespace ncbridge::testing {

std::vector<Motion> tool_path(std::string_view listing) {
  std::vector<Motion> path;
  double last[3] = {NAN, NAN, NAN};
  for (const CanonLine& line : parse_canon_listing(listing)) {
    if (line.name != "STRAIGHT_TRAVERSE" && line.name != "STRAIGHT_FEED" && line.name != "ARC_FEED" &&
        line.name != "STRAIGHT_PROBE") {
      continue;
    }
    Motion m{line.name, {}, line.text};
    for (const std::string& a : line.args) m.values.push_back(std::strtod(a.c_str(), nullptr));
    if (m.values.size() < 6) continue;
    // end point: x y z for straight moves; first, second end and the axis end point for arcs (XY plane)
    double end[3] = {m.values[0], m.values[1], m.name == "ARC_FEED" ? m.values[5] : m.values[2]};
    bool still = m.name != "ARC_FEED" && std::fabs(end[0] - last[0]) < 1e-6 && std::fabs(end[1] - last[1]) < 1e-6 &&
                 std::fabs(end[2] - last[2]) < 1e-6;
    for (int i = 0; i < 3; ++i) last[i] = end[i];
    if (!still) path.push_back(std::move(m));
  }
  return path;
}

PathComparison compare_tool_paths(const std::vector<Motion>& expected, const std::vector<Motion>& actual,
                                  double tolerance) {
  PathComparison result;
  std::size_t n = std::min(expected.size(), actual.size());
  for (std::size_t i = 0; i < n; ++i, ++result.moves) {
    const Motion& e = expected[i];
    const Motion& a = actual[i];
    bool same = e.name == a.name && e.values.size() == a.values.size();
    for (std::size_t k = 0; same && k < e.values.size(); ++k) same = std::fabs(e.values[k] - a.values[k]) <= tolerance;
    if (!same) {
      result.equal = false;
      result.report = "move " + std::to_string(i + 1) + " differs:\n  expected: " + e.text + "\n  actual:   " + a.text;
      return result;
    }
  }
  if (expected.size() != actual.size()) {
    result.equal = false;
    result.report = "expected " + std::to_string(expected.size()) + " moves, got " + std::to_string(actual.size());
    const auto& longer = expected.size() > actual.size() ? expected : actual;
    result.report += "; first extra: " + longer[n].text;
  }
  return result;
}

}  // namespace ncbridge::testing
