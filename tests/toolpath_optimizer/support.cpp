#include "support.hpp"

#include <fstream>
#include <sstream>

#include "ncbridge/toolpath_optimizer/printer_writer.hpp"

namespace ncbridge::toolpath_optimizer::testing {

std::vector<PathPiece> printer_path(const std::string& text, PrinterFlavor flavor) {
  PathRecorder recorder;
  read_printer_text(text, "program.gcode", flavor, recorder);
  return recorder.pieces;
}

PrinterRun optimize_printer_text(const std::string& text, const OptimizerOptions& options, PrinterFlavor flavor) {
  PrinterRun run;
  PrinterWriter writer([&](std::string_view chunk) { run.output.append(chunk); });
  Optimizer optimizer(options, writer);
  read_printer_text(text, "program.gcode", flavor, optimizer);
  run.stats = optimizer.stats();
  DeviationOptions check;
  check.tolerance = options.tolerance_mm;
  run.deviation = check_deviation(printer_path(text, flavor), printer_path(run.output, flavor), check);
  return run;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count_motion_blocks(const std::string& text) {
  std::size_t count = 0;
  int mode = -1;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const std::string code = line.substr(0, std::min(line.find(';'), line.find('(')));
    bool axis = false, g = false, other_word = false;
    int g_mode = -1;
    for (std::size_t i = 0; i < code.size(); ++i) {
      const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(code[i])));
      if (c == 'M' || c == 'T') other_word = true;  // M201 X500 ...: not a motion block
      if (c == 'G') {
        other_word = true;  // G92 E0: the axis words belong to G92
        std::size_t j = i + 1;
        while (j < code.size() && code[j] == '0' && j + 1 < code.size() && std::isdigit(static_cast<unsigned char>(code[j + 1]))) ++j;
        if (j < code.size() && code[j] >= '0' && code[j] <= '3' &&
            (j + 1 >= code.size() || !(std::isdigit(static_cast<unsigned char>(code[j + 1])) || code[j + 1] == '.'))) {
          g = true;
          g_mode = code[j] - '0';
        }
      } else if (std::string_view("XYZABCE").find(c) != std::string_view::npos && i + 1 < code.size() &&
                 (std::isdigit(static_cast<unsigned char>(code[i + 1])) || code[i + 1] == '-' || code[i + 1] == '.' || code[i + 1] == '+')) {
        axis = true;
      }
    }
    if (g) mode = g_mode;
    if (g || (axis && !other_word && mode >= 0)) ++count;
  }
  return count;
}

}  // namespace ncbridge::toolpath_optimizer::testing
