#pragma once
// Test support: two CC2 models compared feature by feature, as the recognition round trip asks:
// same feature entities, centres within 0.01 mm in XY (the centre of what the feature removes,
// its region in the stock: a hole's or pocket's placement, the middle of a face, step or
// profile), tops and depths exact to 1e-4 mm, dimensions within 0.05 mm, and per feature the
// same operations in
// order (entity, tool, strategy entity and the strategy's stated directions). A strategy `$` in
// the first model (the operation leaves it to the generator) is not compared.
#include <string>
#include <vector>

#include "ncbridge/setup/stock.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::test_support {

struct ComparisonTolerances {
  double centre = 0.01;      // mm, in XY
  double height = 1e-4;      // mm: tops and depths
  double dimension = 0.05;   // mm
  double direction = 0.01;   // components of unit vectors
};

struct Cc2Comparison {
  int features = 0;            // features of the first model (TOOLPATH_FEATUREs left out)
  int matched = 0;             // of them, found in the second with the same entity
  int operations = 0, operations_matched = 0;
  std::vector<std::string> differences;  // one line each, "FEATURE: what"
  bool identical() const { return differences.empty(); }
};

// `stock`: the stock both models cut (steps and outside profiles reach to its edge).
Cc2Comparison compare_cc2(const stepnc::Project& expected, const stepnc::Project& actual, const setup::Stock& stock,
                          const ComparisonTolerances& t = {});

}  // namespace ncbridge::test_support
