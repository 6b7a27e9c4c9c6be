// `ncbridge canon PROGRAM`: the interpreter's canonical calls, printed in LinuxCNC rs274's format
// on standard output. PROGRAM "-" reads standard input. An error in the program stops it as it
// stops rs274: the calls made so far, the error, then the driver's reset.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "errors.hpp"
#include "feedback.hpp"
#include "input_files.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/canon_printer.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::cli {

namespace {

struct CanonArguments {
  std::string program;
  std::string tool_table;
  std::string tool_table_units = "mm";
  std::string tools;
  std::string subroutine_path;
  std::string dialect = "rs274ngc";
  std::string heidenhain_feed_units = "mm/min";
  bool strict = false;
  std::vector<int> machine_functions;
};

std::vector<std::filesystem::path> split_path(const std::string& text) {
  std::vector<std::filesystem::path> dirs;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ':')) {
    if (!part.empty()) dirs.emplace_back(part);
  }
  return dirs;
}

int run_canon(const CanonArguments& args, const Feedback& feedback) {
  if (!args.tool_table.empty() && !args.tools.empty()) throw UsageError("--tool-table and --tools: give one tool list");
  if (!args.tool_table.empty()) require_input_file(args.tool_table, "--tool-table");
  if (!args.tools.empty()) require_input_file(args.tools, "--tools");
  const Input program = open_input(args.program, "program");
  interpreter::Options options;
  if (!args.tool_table.empty()) {
    auto units = args.tool_table_units == "inch" ? setup::LengthUnits::Inches : setup::LengthUnits::Millimeters;
    options.tools = setup::read_linuxcnc_tool_table(args.tool_table, units);
  } else if (!args.tools.empty()) {
    options.tools = setup::read_tool_list(args.tools);
  }
  options.subroutine_path = split_path(args.subroutine_path);
  interpreter::parse_dialect_name(args.dialect, options.dialect);
  if (options.dialect == interpreter::Dialect::Auto) {
    // the dialect whose reading takes the whole program (errors are located InputErrors)
    const auto detected = program.text ? interpreter::detect_dialect_reading(*program.text, program.name, options)
                                       : interpreter::detect_dialect_reading(program.path, options);
    options.dialect = detected.dialect;
    feedback.info("dialect " + std::string(interpreter::dialect_name(detected.dialect)) + " (detected: " + detected.reason + ")");
  }
  if (args.heidenhain_feed_units == "mm/s") options.heidenhain_feed_units = interpreter::Options::FeedUnits::PerSecond;
  options.strict = args.strict;
  options.machine_functions = args.machine_functions;
  options.warning = [](const SourceLocation& where, const std::string& message) {
    std::fflush(stdout);
    print_warning(where, message);
  };
  interpreter::CanonPrinter printer(stdout);
  int status = exit_status::ok;
  try {
    if (program.text) {
      interpreter::interpret_text(*program.text, program.name, options, printer);
    } else {
      interpreter::interpret_file(program.path, options, printer);
    }
  } catch (const InputError& e) {
    printer.flush();
    print_error(e);
    status = exit_status::input_error;
  }
  // rs274 resets the interpreter when it stops, whatever the reason.
  printer.print_driver_reset();
  printer.flush();
  return status;
}

}  // namespace

void add_canon_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CanonArguments>();
  CLI::App* cmd = app.add_subcommand("canon", "Interpret a program and print its canonical calls (LinuxCNC rs274 format)");
  cmd->add_option("program", args->program, "Part program; - reads standard input")->required();
  cmd->add_option("--tool-table", args->tool_table, "LinuxCNC tool table (.tbl)");
  cmd->add_option("--tool-table-units", args->tool_table_units, "Units of the tool table values")
      ->check(CLI::IsMember({"mm", "inch"}));
  cmd->add_option("--tools", args->tools, "Tool list (JSON or YAML)");
  cmd->add_option("--subroutine-path", args->subroutine_path, "Directories searched for o<name> call files, ':'-separated");
  cmd->add_option("--dialect", args->dialect, "Program dialect (auto: detect it and say which)")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain", "auto"}));
  cmd->add_option("--heidenhain-feed-units", args->heidenhain_feed_units,
                  "Unit of Heidenhain F words (mm/s for FreeCAD's Heidenhain post; never guessed)")
      ->check(CLI::IsMember({"mm/min", "mm/s"}));
  cmd->add_flag("--strict", args->strict,
                "Refuse what is otherwise read with a warning (machine builder M codes, G43 without tool lengths)");
  cmd->add_option("--machine-functions", args->machine_functions,
                  "M codes that are the machine builder's machine functions (no motion), beyond the dialect's list: "
                  "read with a warning")
      ->delimiter(',');
  cmd->callback([args, cmd, &exit_code]() { exit_code = run_canon(*args, Feedback(verbosity_of(*cmd))); });
}

}  // namespace ncbridge::cli
