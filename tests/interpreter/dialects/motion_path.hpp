#pragma once
// The tool path of a canonical listing (`ncbridge canon` or LinuxCNC rs274 format): its
// STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED and STRAIGHT_PROBE calls in order, compared point by point.
// Moves of zero length are dropped first: a post that leaves out a block whose position does
// not change (Fanuc, Heidenhain) moves the tool exactly as one that writes it.
#include <string>
#include <string_view>
#include <vector>

namespace ncbridge::testing {

struct Motion {
  std::string name;            // STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED, STRAIGHT_PROBE
  std::vector<double> values;  // the call's numeric arguments
  std::string text;            // the listing line, for reports
};

std::vector<Motion> tool_path(std::string_view listing);

struct PathComparison {
  bool equal = true;
  std::size_t moves = 0;  // moves compared
  std::string report;     // where they first differ
};

PathComparison compare_tool_paths(const std::vector<Motion>& expected, const std::vector<Motion>& actual,
                                  double tolerance);

}  // namespace ncbridge::testing
