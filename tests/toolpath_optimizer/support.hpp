#pragma once
// Helpers of the toolpath optimizer tests: printer G-code through the optimizer in memory, read
// back, and measured by the deviation checker.
#include <filesystem>
#include <string>
#include <vector>

#include "ncbridge/toolpath_optimizer/deviation_checker.hpp"
#include "ncbridge/toolpath_optimizer/optimizer.hpp"
#include "ncbridge/toolpath_optimizer/printer_reader.hpp"

namespace ncbridge::toolpath_optimizer::testing {

struct PrinterRun {
  std::string output;
  OptimizerStats stats;
  DeviationReport deviation;
};

// Optimizes printer G-code held in memory, reads the output back and checks it against the input.
PrinterRun optimize_printer_text(const std::string& text, const OptimizerOptions& options,
                                 PrinterFlavor flavor = PrinterFlavor::Marlin);

// The path of printer G-code (loops none).
std::vector<PathPiece> printer_path(const std::string& text, PrinterFlavor flavor = PrinterFlavor::Marlin);

std::string read_file(const std::filesystem::path& path);

// G0..G3 blocks counted as ANCHOR.md counts them: by modal motion mode, a block with axis words and
// no G word continuing the mode; a block is a line with a command (comments and blank lines aside).
std::size_t count_motion_blocks(const std::string& text);

}  // namespace ncbridge::toolpath_optimizer::testing
