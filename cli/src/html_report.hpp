#pragma once
// The --html page of `convert`, `plan` and `gcode`: one self-contained file (inline SVG, CSS and
// scripts, nothing loaded from outside: it opens offline). A top view of the stock (zoom, pan,
// axes at the program zero, a scale bar, the pointer's coordinates in mm), the toolpaths
// coloured by workingstep (rapid moves thin and dashed), the features outlined in their kind's
// colour, a 3D view of the same (three.js, inlined at build time), and a side panel: features
// (a row highlights the feature and the toolpaths that cut it in both views), workingsteps
// (toggles), tools, warnings. Toggles per feature kind, for rapid moves and outlines, and a
// lowest-Z filter act on both views. The scripts: cli/src/html_viewer.js.
//
// It draws any ISO 14649 model: a CC2 model with the toolpaths recognition kept, a CC1 model
// (TOOLPATH_FEATUREs, ROUND_HOLEs), or a CC2 model with the CC1 model generated from it (the
// features of the one, the toolpaths of the other, matched by workingstep id).
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/setup/stock.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::cli {

struct HtmlReportInput {
  std::string title;                  // the program or file converted
  std::string level = "CC2";          // what the page shows, in its title
  std::optional<setup::Stock> stock;  // none: the toolpaths' extent is drawn as the box
  const stepnc::Project* model = nullptr;      // its features and the workingsteps that cut them
  const stepnc::Project* toolpaths = nullptr;  // whose toolpaths are drawn (null: `model`'s)
  std::vector<std::string> setup_warnings;  // "where: message": the setup may be wrong (setup_checks.hpp)
  std::vector<std::string> warnings;        // "where: message": everything else
};

std::string html_report(const HtmlReportInput& input);

}  // namespace ncbridge::cli
