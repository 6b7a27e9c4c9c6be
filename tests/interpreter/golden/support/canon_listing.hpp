#pragma once
// Reading and comparing canonical-call listings in the format of LinuxCNC's standalone `rs274`
// (and `ncbridge canon`): `%5d N..... NAME(args)`, one call a line.
#include <string>
#include <string_view>
#include <vector>

namespace ncbridge::testing {

struct CanonLine {
  std::string n_column;          // "N.....", "N10", "N0010"
  std::string name;              // "STRAIGHT_FEED"
  std::vector<std::string> args; // split on commas and blanks; a quoted string is one argument
  std::string text;              // the line as printed, for reports
};

// Parses a listing; lines that are not canonical calls are kept with an empty name, so that
// they show up as differences instead of being skipped.
std::vector<CanonLine> parse_canon_listing(std::string_view listing);

struct ListingComparison {
  bool equal = true;
  std::string report;  // when not equal: where the listings first differ, with context
};

// Call for call: same names in the same order, the same N column, numeric arguments within
// `tolerance`, other arguments identical.
ListingComparison compare_canon_listings(const std::vector<CanonLine>& expected,
                                         const std::vector<CanonLine>& actual,
                                         double tolerance = 1e-4);

}  // namespace ncbridge::testing
