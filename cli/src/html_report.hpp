#pragma once
// `ncbridge convert --html OUT.html`: one self-contained page (inline SVG, CSS and scripts, no
// external resources: it opens offline) with a top view of the stock (zoom and pan), the
// toolpaths coloured by workingstep, the recognised features outlined and labelled, a 3D view
// of stock, toolpaths and features (three.js, inlined at build time; views, lowest-Z cut), and a
// side panel listing features (a row highlights its outline), workingsteps (toggles, highlight
// on hover), tools and warnings. The scripts: cli/src/html_viewer.js.
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
