// `ncbridge optimize PROGRAM -o OUT`: the toolpath optimizer (docs/optimize.md). Printer G-code
// (--flavor) or a CNC program (--dialect) in; printer G-code, a CNC dialect or KUKA KRL out. The
// outputs (the program, a KRL .dat beside a .src, the report) appear together or not at all.
#include <CLI/CLI.hpp>

#include <cctype>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "errors.hpp"
#include "feedback.hpp"
#include "input_files.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/gcode_writer/dialect.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/toolpath_optimizer/canonical_bridge.hpp"
#include "ncbridge/toolpath_optimizer/krl.hpp"
#include "ncbridge/toolpath_optimizer/pipeline.hpp"
#include "ncbridge/toolpath_optimizer/printer_reader.hpp"
#include "optimize_html.hpp"
#include "output_files.hpp"

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
  std::string output;
  std::string report;
  std::string html;
  std::optional<std::size_t> html_layer;
  std::optional<double> html_z;
  double tolerance = 0.025;
  double min_segment = 0;
  double max_radius = 10000;
  double extrusion_variance = 0.05;
  bool loops = false;
  bool no_arcs = false;
  bool no_helical = false;
  bool no_check = false;
  int krl_base = 1;
  int krl_tool = 1;
  std::optional<int> decimals;
};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Without --tools: tools 0..99 of length and diameter 0. Positions are program-frame, so tool
// lengths do not move the path; the program's G43 H.. and T.. M6 read.
setup::ToolList tools_without_dimensions() {
  std::vector<setup::Tool> tools;
  for (int n = 0; n <= 99; ++n) {
    setup::Tool t;
    t.number = n;
    t.pocket = n;
    tools.push_back(t);
  }
  return setup::ToolList(std::move(tools));
}

// What the program is (--flavor or --dialect, or a .gcode/.gco file), and what to write.
void read_kinds(const OptimizeArguments& args, toolpath_optimizer::OptimizeRequest& request, const Feedback& feedback) {
  using namespace toolpath_optimizer;
  if (!args.flavor.empty() && !args.dialect.empty()) {
    throw UsageError("--flavor (printer G-code) or --dialect (a CNC program), not both");
  }
  if (args.flavor.empty() && args.dialect.empty()) {
    const std::string ext = lower(fs::path(args.program).extension().string());
    if (ext != ".gcode" && ext != ".gco") {
      throw UsageError("say what the program is: --flavor marlin|reprap|klipper (printer G-code) or "
                       "--dialect rs274ngc|fanuc|mach3|siemens840d|heidenhain|auto");
    }
  }
  if (!args.flavor.empty() && !parse_printer_flavor(args.flavor, request.flavor)) {
    throw UsageError("unknown --flavor \"" + args.flavor + "\" (marlin, reprap, klipper)");
  }
  if (!args.dialect.empty()) {
    request.input_kind = InputKind::Cnc;
    if (!interpreter::parse_dialect_name(args.dialect, request.cnc.dialect)) {
      throw UsageError("unknown --dialect \"" + args.dialect + "\" (rs274ngc, fanuc, mach3, siemens840d, heidenhain, auto)");
    }
    if (request.cnc.dialect == interpreter::Dialect::Auto) {
      const auto detected = interpreter::detect_dialect_file(args.program);
      request.cnc.dialect = detected.dialect;
      feedback.info("dialect " + std::string(interpreter::dialect_name(detected.dialect)) + " (detected: " + detected.reason + ")");
    }
    request.cnc.require_program_end = false;  // the last block ends it, as on the control
    request.cnc.tools = args.tools.empty() ? tools_without_dimensions() : setup::read_tool_list(args.tools);
    if (args.heidenhain_feed_units == "mm/s") request.cnc.heidenhain_feed_units = interpreter::Options::FeedUnits::PerSecond;
    std::stringstream dirs(args.subroutine_path);
    for (std::string d; std::getline(dirs, d, ':');) {
      if (!d.empty()) request.cnc.subroutine_path.emplace_back(d);
    }
  }
  // Where to: the input's own kind unless --to says otherwise.
  const std::string to = lower(args.to);
  if (to == "krl") {
    request.output = OutputFormat::Krl;
  } else if (to.empty() || to == "gcode") {
    if (request.input_kind == InputKind::Cnc) {
      if (to == "gcode") throw UsageError("--to gcode is printer G-code: a CNC program goes --to a dialect or krl");
      request.output = OutputFormat::Cnc;
      request.writer.dialect = *gcode_writer::parse_dialect(interpreter::dialect_name(request.cnc.dialect));
    }
  } else if (const auto dialect = gcode_writer::parse_dialect(to)) {
    if (request.input_kind != InputKind::Cnc) {
      throw UsageError("printer G-code is written as printer G-code (--to gcode) or KRL (--to krl)");
    }
    request.output = OutputFormat::Cnc;
    request.writer.dialect = *dialect;
  } else {
    throw UsageError("unknown --to \"" + args.to + "\" (gcode, krl, rs274ngc, fanuc, mach3, siemens840d, heidenhain)");
  }
  if (request.loops && request.output == OutputFormat::PrinterGcode) {
    throw UsageError("printer G-code has no loop construct: --loops needs --to krl (or a CNC dialect for a CNC program)");
  }
}

// The name a program carries (KRL module, Heidenhain/SINUMERIK program name): the output's stem.
std::string program_name(const std::string& output) {
  const std::string stem = fs::path(output).stem().string();
  return toolpath_optimizer::krl_module_name(stem.empty() || stem == "-" ? "program" : stem);
}

// The --html page: the input and the written output read back as the deviation checker reads
// them (each by its own front-end, loops expanded), one layer drawn.
std::string optimize_page(const OptimizeArguments& args, const toolpath_optimizer::OptimizeRequest& request,
                          const toolpath_optimizer::OptimizeResult& result, const std::string& written, const std::string& output_name) {
  using namespace toolpath_optimizer;
  PathRecorder before, after;
  if (request.input_kind == InputKind::Cnc) {
    CanonicalFrontEnd front_end(before);
    interpreter::interpret_file(request.input, request.cnc, front_end);
  } else {
    read_printer_file(request.input, request.flavor, before);
  }
  if (request.output == OutputFormat::Krl) {
    read_krl_text(written, output_name, after);
  } else if (request.output == OutputFormat::Cnc) {
    interpreter::Options reading;
    interpreter::parse_dialect_name(gcode_writer::dialect_name(request.writer.dialect), reading.dialect);
    reading.tools = request.writer.tools;
    reading.require_program_end = false;
    CanonicalFrontEnd front_end(after);
    interpreter::interpret_text(written, output_name, reading, front_end);
  } else {
    read_printer_text(written, output_name, request.flavor, after);
  }
  OptimizeHtmlInput page;
  page.program = fs::path(args.program).filename().string();
  page.output = fs::path(output_name).filename().string();
  page.before = &before.pieces;
  page.after = &after.pieces;
  page.result = &result;
  page.tolerance = args.tolerance;
  page.printer = request.input_kind == InputKind::Printer;
  page.layer = args.html_layer;
  page.z = args.html_z;
  return optimize_html(page);
}

int run_optimize(const OptimizeArguments& args, Verbosity verbosity) {
  using namespace toolpath_optimizer;
  Feedback feedback(verbosity);
  if (!(args.tolerance > 0)) throw UsageError("--tolerance must be greater than 0 (mm)");
  if (args.min_segment < 0) throw UsageError("--min-segment must not be negative");
  if (!(args.max_radius > 0)) throw UsageError("--max-radius must be greater than 0");
  if (!(args.extrusion_variance >= 0)) throw UsageError("--extrusion-variance must not be negative");
  require_input_file(args.program, "program");

  OptimizeRequest request;
  request.input = args.program;
  request.loops = args.loops;
  request.check = !args.no_check;
  request.optimizer.tolerance_mm = args.tolerance;
  request.optimizer.min_segment_mm = args.min_segment;
  request.optimizer.max_radius_mm = args.max_radius;
  request.optimizer.extrusion_rate_variance = args.extrusion_variance;
  request.optimizer.arcs = !args.no_arcs;
  request.optimizer.helical = !args.no_helical;
  read_kinds(args, request, feedback);

  OutputSet outputs;
  outputs.protect(args.program);
  if (!args.tools.empty()) outputs.protect(args.tools);
  OutputFile& out = outputs.add(args.output, "-o");
  OutputFile* dat = nullptr;
  if (request.output == OutputFormat::Krl) {
    const fs::path src(args.output);
    if (lower(src.extension().string()) != ".src") {
      throw UsageError("KRL output is NAME.src (its NAME.dat is written beside it): -o " + args.output);
    }
    fs::path dat_path = src;
    dat_path.replace_extension(src.extension() == ".SRC" ? ".DAT" : ".dat");
    dat = &outputs.add(dat_path.string(), "-o (the .dat)");
    request.krl.name = program_name(args.output);
    request.krl.base = args.krl_base;
    request.krl.tool = args.krl_tool;
  }
  if (request.output == OutputFormat::Cnc) {
    request.writer.program_name = program_name(args.output);
    request.writer.decimals = args.decimals;
    request.writer.tools = request.cnc.tools;
  }
  OutputFile* report = args.report.empty() ? nullptr : &outputs.add(args.report, "--report");
  if (args.html.empty() && (args.html_layer || args.html_z)) throw UsageError("--html-layer and --html-z choose the layer --html draws");
  if (args.html_layer && args.html_z) throw UsageError("--html-layer or --html-z, not both");
  OutputFile* html = args.html.empty() ? nullptr : &outputs.add(args.html, "--html");
  request.output_name = out.display_name();

  Progress progress(feedback.progress_wanted());
  request.progress = [&progress](std::uint64_t line) { progress.set("optimizing: line " + std::to_string(line)); };
  OutputSinks sinks;
  std::string written;  // for the page
  sinks.main = [&](std::string_view chunk) {
    out.write(chunk);
    if (html) written.append(chunk);
  };
  sinks.data = [&](std::string_view chunk) {
    if (dat) dat->write(chunk);
  };
  const OptimizeResult result = optimize(request, sinks);
  progress.stop();
  if (report) report->write(report_json(request, result));
  if (html) {
    progress.set("drawing the page");
    html->write(optimize_page(args, request, result, written, out.display_name()));
    progress.stop();
  }
  outputs.commit();
  feedback.summary(out.display_name() + ": " + summary_line(request, result));
  return exit_status::ok;
}

}  // namespace

void add_optimize_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<OptimizeArguments>();
  CLI::App* cmd = app.add_subcommand("optimize", "Rewrite a linearised toolpath with merged lines, arcs and loops");
  cmd->add_option("program", args->program, "Printer G-code (--flavor) or a CNC program (--dialect)")->required();
  cmd->add_option("--flavor", args->flavor, "Printer firmware the G-code is for: marlin, reprap, klipper");
  cmd->add_option("--dialect", args->dialect, "CNC program dialect: rs274ngc, fanuc, mach3, siemens840d, heidenhain, auto");
  cmd->add_option("--to", args->to,
                  "Output: gcode (printer G-code, default for --flavor), krl, or a CNC dialect (default: the input's)");
  cmd->add_option("-o,--output", args->output, "Output file (KRL: NAME.src, and NAME.dat beside it)")->required();
  cmd->add_option("--report", args->report, "Also write a JSON report (docs/formats/optimize-report.md)");
  cmd->add_option("--html", args->html, "Also write an HTML page: one layer before and after (docs/optimize.md)");
  cmd->add_option("--html-layer", args->html_layer, "The layer the page draws, 1 = the first the program cuts (default: the middle one)");
  cmd->add_option("--html-z", args->html_z, "The layer the page draws, by its Z in mm");
  cmd->add_option("--tolerance", args->tolerance, "Deviation band in mm, both ways (default 0.025)");
  cmd->add_option("--min-segment", args->min_segment, "Fold moves shorter than this (mm) into their neighbours");
  cmd->add_option("--max-radius", args->max_radius, "Largest arc radius in mm (default 10000)");
  cmd->add_option("--extrusion-variance", args->extrusion_variance,
                  "How much the filament per length may vary inside one fitted move (default 0.05)");
  cmd->add_flag("--loops", args->loops, "Write repeated layers once, as a loop (KRL FOR, the dialect's repeat)");
  cmd->add_flag("--no-arcs", args->no_arcs, "Merge lines only");
  cmd->add_flag("--no-helical", args->no_helical, "Only arcs whose normal axis stays put");
  cmd->add_flag("--no-check", args->no_check, "Skip reading the output back through the deviation checker");
  cmd->add_option("--tools", args->tools, "Tool list of a CNC program (JSON or YAML, docs/formats/tools.md)");
  cmd->add_option("--subroutine-path", args->subroutine_path, "Directories searched for o<name> call files, ':'-separated");
  cmd->add_option("--heidenhain-feed-units", args->heidenhain_feed_units, "Unit of Heidenhain F words (mm/min or mm/s)")
      ->check(CLI::IsMember({"mm/min", "mm/s"}));
  cmd->add_option("--decimals", args->decimals, "CNC output: digits after the point in mm (default 4, one more in inches)");
  cmd->add_option("--krl-base", args->krl_base, "KRL: BASE_DATA index of the part's frame (default 1)");
  cmd->add_option("--krl-tool", args->krl_tool, "KRL: TOOL_DATA index of the tool (default 1)");
  cmd->callback([args, cmd, &exit_code]() { exit_code = run_optimize(*args, verbosity_of(*cmd)); });
}

}  // namespace ncbridge::cli
