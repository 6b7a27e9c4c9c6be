#pragma once
// `ncbridge optimize` as one call: a front-end (printer G-code, or a CNC program through the
// interpreter), the optimizer, a writer, and the deviation checker reading the written text back
// with the output's own front-end. The caller owns the output files (and commits them only when
// this returns).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "ncbridge/gcode_writer/options.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/toolpath_optimizer/deviation_checker.hpp"
#include "ncbridge/toolpath_optimizer/krl.hpp"
#include "ncbridge/toolpath_optimizer/loop_detector.hpp"
#include "ncbridge/toolpath_optimizer/optimizer.hpp"
#include "ncbridge/toolpath_optimizer/printer_reader.hpp"

namespace ncbridge::toolpath_optimizer {

enum class OutputFormat : std::uint8_t {
  PrinterGcode,  // the input's own flavour
  Krl,           // KUKA KRL .src and .dat
  Cnc,           // a CNC dialect, through the gcode_writer (`writer.dialect`)
};

enum class InputKind : std::uint8_t {
  Printer,  // printer G-code, `flavor`
  Cnc,      // a CNC program in `cnc.dialect`, through the interpreter
};

struct OptimizeRequest {
  std::filesystem::path input;
  InputKind input_kind = InputKind::Printer;
  PrinterFlavor flavor = PrinterFlavor::Marlin;
  interpreter::Options cnc;          // dialect, tools, subroutine path
  OutputFormat output = OutputFormat::PrinterGcode;
  std::string output_name;           // for messages
  OptimizerOptions optimizer;
  bool loops = false;                // repeated layers as loops (not for printer G-code)
  LoopOptions loop;
  KrlOptions krl;                    // --to krl: name, frames, home; the rest is set from the input
  gcode_writer::Options writer;      // a CNC dialect: dialect, program name, decimals, tools
  bool check = true;                 // read the output back and measure the deviation
  // Called now and then with the input bytes read so far (progress display).
  std::function<void(std::uint64_t)> progress;
};

struct OptimizeResult {
  std::uint64_t bytes_in = 0, lines_in = 0, commands_in = 0, motion_blocks_in = 0, arcs_in = 0;
  std::uint64_t bytes_out = 0, lines_out = 0, commands_out = 0, motion_blocks_out = 0;
  OptimizerStats stats;
  LoopStats loops;
  std::optional<DeviationReport> deviation;  // when checked
  double optimize_seconds = 0;               // read, optimize, write
  double check_seconds = 0;                  // the deviation checker's share of it
  std::size_t check_pieces_held = 0;         // the most path pieces the checker held at once
};

// Where the output goes: the program (printer G-code, KRL .src) and, for KRL, the .dat.
struct OutputSinks {
  std::function<void(std::string_view)> main;
  std::function<void(std::string_view)> data;
};

// Throws InputError for bad input, std::runtime_error when the written output does not stay
// within the band (a bug: the caller must not commit the output then).
OptimizeResult optimize(const OptimizeRequest& request, const OutputSinks& output);

// The one-line summary `ncbridge optimize` prints on stderr.
std::string summary_line(const OptimizeRequest& request, const OptimizeResult& result);

// The --report JSON (docs/formats/optimize-report.md).
std::string report_json(const OptimizeRequest& request, const OptimizeResult& result);

}  // namespace ncbridge::toolpath_optimizer
