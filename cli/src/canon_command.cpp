// `ncbridge canon PROGRAM`: the interpreter's canonical calls, printed in LinuxCNC rs274's format.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
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

int run_canon(const CanonArguments& args) {
  interpreter::Options options;
  try {
    if (!args.tool_table.empty()) {
      auto units = args.tool_table_units == "inch" ? setup::LengthUnits::Inches : setup::LengthUnits::Millimeters;
      options.tools = setup::read_linuxcnc_tool_table(args.tool_table, units);
    } else if (!args.tools.empty()) {
      options.tools = setup::read_tool_list(args.tools);
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  options.subroutine_path = split_path(args.subroutine_path);
  interpreter::parse_dialect_name(args.dialect, options.dialect);
  if (options.dialect == interpreter::Dialect::Auto) {
    try {
      const auto detected = interpreter::detect_dialect_reading(args.program, options);
      options.dialect = detected.dialect;
      std::fprintf(stderr, "ncbridge: dialect %s (detected: %s)\n",
                   std::string(interpreter::dialect_name(detected.dialect)).c_str(), detected.reason.c_str());
    } catch (const InputError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 1;
    }
  }
  if (args.heidenhain_feed_units == "mm/s") options.heidenhain_feed_units = interpreter::Options::FeedUnits::PerSecond;
  options.strict = args.strict;
  options.machine_functions = args.machine_functions;
  options.warning = [](const SourceLocation& where, const std::string& message) {
    std::fprintf(stderr, "%s: warning: %s\n", where.to_string().c_str(), message.c_str());
  };
  interpreter::CanonPrinter printer(stdout);
  int status = 0;
  try {
    interpreter::interpret_file(args.program, options, printer);
  } catch (const InputError& e) {
    printer.flush();
    std::fprintf(stderr, "%s\n", e.what());
    status = 1;
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
  cmd->add_option("program", args->program, "RS274/NGC program")->required()->check(CLI::ExistingFile);
  cmd->add_option("--tool-table", args->tool_table, "LinuxCNC tool table (.tbl)")->check(CLI::ExistingFile);
  cmd->add_option("--tool-table-units", args->tool_table_units, "Units of the tool table values")
      ->check(CLI::IsMember({"mm", "inch"}));
  cmd->add_option("--tools", args->tools, "Tool list (JSON or YAML)")->check(CLI::ExistingFile);
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
  cmd->callback([args, &exit_code]() { exit_code = run_canon(*args); });
}

}  // namespace ncbridge::cli
