#pragma once
// `ncbridge convert --html OUT.html`: one self-contained page (inline SVG and CSS, no external
// resources) with a top view of the stock, the toolpaths coloured by workingstep, the
// recognised features outlined and labelled, and a side panel listing features, operations,
// tools and warnings.
#include <string>
#include <vector>

#include "cc2_output.hpp"

namespace ncbridge::cli {

struct HtmlReportInput {
  std::string title;                  // the program or file converted
  const Cc2Output* cc2 = nullptr;     // features, ids and the CC2 workplan (toolpaths, tools)
  std::vector<std::string> setup_warnings;  // "where: message": the setup may be wrong (setup_checks.hpp)
  std::vector<std::string> warnings;        // "where: message": everything else
};

std::string html_report(const HtmlReportInput& input);

}  // namespace ncbridge::cli
