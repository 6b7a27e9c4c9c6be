#pragma once
// `ncbridge optimize --html P.html`: one self-contained page (inline SVG and script, opens
// offline) with one layer of the program before and after: the input's motions (the vertices
// of a linearised curve shown as dots) beside the output's lines and arcs (each drawn in its own
// colour, its ends as dots), on the same scale, zoom and pan linked; the counts of the layer and
// of the whole run; and a table of every layer with its counts, to choose another with
// --html-layer N or --html-z Z. Paths as the deviation checker reads them (mm, loops expanded).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/toolpath_optimizer/deviation_checker.hpp"
#include "ncbridge/toolpath_optimizer/pipeline.hpp"

namespace ncbridge::cli {

struct OptimizeHtmlInput {
  std::string program;  // the input's name
  std::string output;   // the output's name
  const std::vector<toolpath_optimizer::PathPiece>* before = nullptr;
  const std::vector<toolpath_optimizer::PathPiece>* after = nullptr;
  const toolpath_optimizer::OptimizeResult* result = nullptr;
  double tolerance = 0;
  bool printer = false;  // printer G-code: a move without extrusion is travel
  std::optional<std::size_t> layer;  // 1-based, in the order the input reaches them
  std::optional<double> z;           // mm
};

// Throws UsageError when the layer asked for is not in the program.
std::string optimize_html(const OptimizeHtmlInput& input);

}  // namespace ncbridge::cli
