// printer_deviation INPUT OUTPUT TOLERANCE: how far OUTPUT (printer G-code, Marlin) strays from
// INPUT, measured by the optimizer's deviation checker. Prints one line: the largest distances
// both ways, the largest filament difference and the number of spans that leave the band (with
// the first). Exit 0 within the band, 1 outside it, 2 on bad arguments or input.
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "ncbridge/toolpath_optimizer/deviation_checker.hpp"
#include "ncbridge/toolpath_optimizer/printer_reader.hpp"

namespace {

std::vector<ncbridge::toolpath_optimizer::PathPiece> path_of(const char* file) {
  using namespace ncbridge::toolpath_optimizer;
  PathRecorder recorder;
  read_printer_file(file, PrinterFlavor::Marlin, recorder);
  return std::move(recorder.pieces);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ncbridge::toolpath_optimizer;
  if (argc != 4) {
    std::fprintf(stderr, "usage: printer_deviation INPUT OUTPUT TOLERANCE_MM\n");
    return 2;
  }
  try {
    DeviationOptions options;
    options.tolerance = std::atof(argv[3]);
    const DeviationReport r = check_deviation(path_of(argv[1]), path_of(argv[2]), options);
    std::printf("largest %.4f mm (input to output %.4f, output to input %.4f), filament %.5f mm, %zu spans out of the band%s%s\n",
                r.largest(), r.input_to_output, r.output_to_input, r.extrusion_error,
                static_cast<std::size_t>(r.problem_count), r.problems.empty() ? "" : ": ",
                r.problems.empty() ? "" : r.problems.front().c_str());
    return r.passed(options.tolerance) ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "printer_deviation: %s\n", e.what());
    return 2;
  }
}
