// `ncbridge optimize PROGRAM -o OUT`: the toolpath optimizer (docs/optimize.md). The output (and
// the report) are written atomically: a failed run leaves no file.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/atomic_file.hpp"
#include "ncbridge/toolpath_optimizer/pipeline.hpp"

namespace ncbridge::cli {

namespace {

namespace fs = std::filesystem;

struct OptimizeArguments {
  std::string program;
  std::string flavor;
  std::string dialect;
  std::string tools;
  std::string subroutine_path;
  std::string heidenhain_feed_units = "mm/min";
  std::string to;
  bool loops = false;
  int krl_base = 1;
  int krl_tool = 1;
  std::string output;
  std::string report;
  double tolerance = 0.025;
  double min_segment = 0;
  double max_radius = 10000;
  double extrusion_variance = 0.05;
  bool no_arcs = false;
  bool no_helical = false;
  bool no_check = false;
};

int run_optimize(const OptimizeArguments& args) {
  using namespace toolpath_optimizer;
  OptimizeRequest request;
  request.input = args.program;
  if (!args.flavor.empty() && !args.dialect.empty()) {
    throw InputError({args.program, 0, 0}, "--flavor (printer G-code) or --dialect (a CNC program), not both");
  }
  if (args.flavor.empty() && args.dialect.empty()) {
    std::string ext = fs::path(args.program).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".gcode" && ext != ".gco") {
      throw InputError({args.program, 0, 0}, "say what the program is: --flavor marlin|reprap|klipper (printer G-code) "
                                             "or --dialect rs274ngc|fanuc|mach3|siemens840d|heidenhain|auto");
    }
  }
  if (!args.flavor.empty() && !parse_printer_flavor(args.flavor, request.flavor)) {
    throw InputError({args.program, 0, 0}, "unknown --flavor \"" + args.flavor + "\" (marlin, reprap, klipper)");
  }
  if (!args.dialect.empty()) {
    request.input_kind = InputKind::Cnc;
    if (!interpreter::parse_dialect_name(args.dialect, request.cnc.dialect)) {
      throw InputError({args.program, 0, 0}, "unknown --dialect \"" + args.dialect +
                                                 "\" (rs274ngc, fanuc, mach3, siemens840d, heidenhain, auto)");
    }
    if (request.cnc.dialect == interpreter::Dialect::Auto) {
      const auto detected = interpreter::detect_dialect_file(args.program);
      request.cnc.dialect = detected.dialect;
      std::fprintf(stderr, "ncbridge: dialect %s (detected: %s)\n", std::string(interpreter::dialect_name(detected.dialect)).c_str(),
                   detected.reason.c_str());
    }
    request.cnc.require_program_end = false;
    if (!args.tools.empty()) {
      request.cnc.tools = setup::read_tool_list(args.tools);
    } else {
      // Positions are program-frame: lengths do not move the path. Tools 0..99 of length and
      // diameter 0 let G43 H.. and T.. M6 read (docs/optimize.md).
      std::vector<setup::Tool> tools;
      for (int n = 0; n <= 99; ++n) {
        setup::Tool t;
        t.number = n;
        t.pocket = n;
        tools.push_back(t);
      }
      request.cnc.tools = setup::ToolList(std::move(tools));
    }
    if (args.heidenhain_feed_units == "mm/s") request.cnc.heidenhain_feed_units = interpreter::Options::FeedUnits::PerSecond;
    std::stringstream dirs(args.subroutine_path);
    for (std::string d; std::getline(dirs, d, ':');) {
      if (!d.empty()) request.cnc.subroutine_path.emplace_back(d);
    }
  }
  if (!(args.tolerance > 0)) throw InputError({args.program, 0, 0}, "--tolerance must be greater than 0");
  if (args.min_segment < 0) throw InputError({args.program, 0, 0}, "--min-segment must not be negative");
  request.output_name = args.output;
  request.optimizer.tolerance_mm = args.tolerance;
  request.optimizer.min_segment_mm = args.min_segment;
  request.optimizer.max_radius_mm = args.max_radius;
  request.optimizer.extrusion_rate_variance = args.extrusion_variance;
  request.optimizer.arcs = !args.no_arcs;
  request.optimizer.helical = !args.no_helical;
  request.check = !args.no_check;
  request.loops = args.loops;
  if (args.to == "krl") {
    request.output = OutputFormat::Krl;
  } else if (!args.to.empty() && args.to != "gcode") {
    throw InputError({args.program, 0, 0}, "unknown --to \"" + args.to + "\" (gcode, krl)");
  } else if (request.input_kind == InputKind::Cnc) {
    throw InputError({args.program, 0, 0}, "a CNC program is written with --to krl");
  }
  const fs::path output(args.output);
  fs::path dat;
  if (request.output == OutputFormat::Krl) {
    std::string ext = output.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".src") throw InputError({args.output, 0, 0}, "KRL output is a .src file (its .dat is written beside it)");
    dat = output;
    dat.replace_extension(output.extension() == ".SRC" ? ".DAT" : ".dat");
    request.krl.name = krl_module_name(output.stem().string());
    request.krl.base = args.krl_base;
    request.krl.tool = args.krl_tool;
  }
  bool shown = false;
  if (isatty(STDERR_FILENO)) {
    request.progress = [&shown](std::uint64_t line) {
      std::fprintf(stderr, "\roptimizing: line %llu", static_cast<unsigned long long>(line));
      std::fflush(stderr);
      shown = true;
    };
  }
  auto clear = [&] {
    if (shown) std::fprintf(stderr, "\r\033[K");
    shown = false;
  };
  step_writer::AtomicFile file(args.output);
  std::optional<step_writer::AtomicFile> dat_file;
  if (!dat.empty()) dat_file.emplace(dat);
  OutputSinks sinks;
  sinks.main = [&](std::string_view chunk) { file.write(chunk); };
  sinks.data = [&](std::string_view chunk) { dat_file->write(chunk); };
  OptimizeResult result;
  try {
    result = optimize(request, sinks);
  } catch (...) {
    clear();
    throw;
  }
  clear();
  // The .src and its .dat both or neither: the .dat first; if the .src then cannot be put in
  // place, the new .dat goes too.
  if (dat_file) dat_file->commit();
  try {
    file.commit();
  } catch (...) {
    if (dat_file) {
      std::error_code ignored;
      fs::remove(dat, ignored);
    }
    throw;
  }
  if (!args.report.empty()) step_writer::write_file_atomically(args.report, report_json(request, result));
  std::fprintf(stderr, "%s\n", summary_line(request, result).c_str());
  return 0;
}

}  // namespace

void add_optimize_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<OptimizeArguments>();
  CLI::App* cmd = app.add_subcommand("optimize", "Rewrite a linearised toolpath with merged lines, arcs and loops");
  cmd->add_option("program", args->program, "Printer G-code (--flavor) or a CNC program (--dialect)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--flavor", args->flavor, "Printer firmware the G-code is for: marlin, reprap, klipper");
  cmd->add_option("--dialect", args->dialect, "CNC program dialect: rs274ngc, fanuc, mach3, siemens840d, heidenhain, auto");
  cmd->add_option("--tools", args->tools, "Tool list of a CNC program (JSON or YAML, docs/formats/tools.md)")->check(CLI::ExistingFile);
  cmd->add_option("--subroutine-path", args->subroutine_path, "Directories searched for o<name> call files, ':'-separated");
  cmd->add_option("--heidenhain-feed-units", args->heidenhain_feed_units, "Unit of Heidenhain F words (mm/min or mm/s)")
      ->check(CLI::IsMember({"mm/min", "mm/s"}));
  cmd->add_option("-o,--output", args->output, "Output file (KRL: NAME.src, and NAME.dat beside it)")->required();
  cmd->add_option("--to", args->to, "Output: gcode (the input's flavour, default) or krl");
  cmd->add_flag("--loops", args->loops, "Write repeated layers once, as a loop (KRL FOR)");
  cmd->add_option("--krl-base", args->krl_base, "KRL: BASE_DATA index of the part's frame (default 1)");
  cmd->add_option("--krl-tool", args->krl_tool, "KRL: TOOL_DATA index of the tool (default 1)");
  cmd->add_option("--report", args->report, "Also write a JSON report (docs/formats/optimize-report.md)");
  cmd->add_option("--tolerance", args->tolerance, "Deviation band in mm, both ways (default 0.025)");
  cmd->add_option("--min-segment", args->min_segment, "Fold moves shorter than this (mm) into their neighbours");
  cmd->add_option("--max-radius", args->max_radius, "Largest arc radius in mm (default 10000)");
  cmd->add_option("--extrusion-variance", args->extrusion_variance,
                  "How much the filament per length may vary inside one fitted move (default 0.05)");
  cmd->add_flag("--no-arcs", args->no_arcs, "Merge lines only");
  cmd->add_flag("--no-helical", args->no_helical, "Only arcs whose normal axis stays put");
  cmd->add_flag("--no-check", args->no_check, "Skip reading the output back through the deviation checker");
  cmd->callback([args, &exit_code]() { exit_code = run_optimize(*args); });
}

}  // namespace ncbridge::cli
