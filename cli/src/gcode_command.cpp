// `ncbridge gcode INPUT --to DIALECT -o OUT`: a program (any dialect the interpreter reads) or a
// CC1 STEP-NC file written as a program in one of the five dialects (docs/gcode.md). Embedded
// pipeline: interpreter (or the STEP-NC interpreter) -> gcode_writer, streamed into an atomic
// output file: a failed run leaves no file (and an old OUT untouched).
#include <CLI/CLI.hpp>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/gcode_writer/program_writer.hpp"
#include "ncbridge/gcode_writer/stepnc_interpreter.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/atomic_file.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

namespace ncbridge::cli {

namespace {

struct GcodeArguments {
  std::string input;
  std::string to;
  std::string output;
  std::string dialect = "auto";
  std::string tool_table;
  std::string tool_table_units = "mm";
  std::string tools;
  std::string subroutine_path;
  std::string heidenhain_feed_units = "mm/min";
  std::string comments = "program";
  std::optional<int> decimals;
  std::optional<bool> block_numbers;
  bool block_numbers_flag = false;
  std::optional<std::uint32_t> program_number;
  std::string program_name;
  bool drop_path_tolerance = false;
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

// A Part 21 file opens with ISO-10303-21; after any white space and /* comments */.
bool is_part21(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(8192, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::size_t i = 0;
  while (i < head.size()) {
    if (std::isspace(static_cast<unsigned char>(head[i]))) {
      ++i;
    } else if (head.compare(i, 2, "/*") == 0) {
      const std::size_t end = head.find("*/", i + 2);
      if (end == std::string::npos) return false;
      i = end + 2;
    } else {
      break;
    }
  }
  return head.compare(i, 13, "ISO-10303-21;") == 0;
}

// The program name the dialects print (O-number comment, BEGIN PGM, MPF name): the output's
// stem in capitals, letters, digits and _ only.
std::string name_from(const std::string& output) {
  std::string name;
  for (char c : std::filesystem::path(output).stem().string()) {
    const auto u = static_cast<unsigned char>(c);
    name.push_back(std::isalnum(u) ? static_cast<char>(std::toupper(u)) : '_');
  }
  return name.empty() ? "NCBRIDGE" : name;
}

setup::ToolList read_tools(const GcodeArguments& args) {
  if (!args.tool_table.empty()) {
    const auto units = args.tool_table_units == "inch" ? setup::LengthUnits::Inches : setup::LengthUnits::Millimeters;
    return setup::read_linuxcnc_tool_table(args.tool_table, units);
  }
  if (!args.tools.empty()) return setup::read_tool_list(args.tools);
  return {};
}

int run_gcode(const GcodeArguments& args) {
  gcode_writer::Options options;
  options.dialect = *gcode_writer::parse_dialect(args.to);
  options.tools = read_tools(args);
  options.program_name = args.program_name.empty() ? name_from(args.output) : args.program_name;
  if (args.program_number) options.program_number = *args.program_number;
  options.decimals = args.decimals;
  options.block_numbers = args.block_numbers;
  options.drop_path_tolerance = args.drop_path_tolerance;
  options.comments = args.comments == "none"     ? gcode_writer::Comments::None
                     : args.comments == "source" ? gcode_writer::Comments::Source
                                                 : gcode_writer::Comments::Program;

  if (is_part21(args.input)) {
    // a CC1 file: the STEP-NC interpreter's calls; the program runs with the file's tools
    // unless a tool list is given
    const auto read = step_writer::read_stepnc_file(args.input);
    for (const auto& w : read.warnings) std::fprintf(stderr, "%s\n", w.to_string().c_str());
    if (options.tools.empty()) options.tools = gcode_writer::stepnc_tools(read.project);
    gcode_writer::StepncOptions stepnc;
    if (options.comments == gcode_writer::Comments::Source) {
      stepnc.name_workingsteps = true;  // a workingstep's name says where its blocks come from
      options.comments = gcode_writer::Comments::Program;
    }
    step_writer::AtomicFile file(args.output);
    gcode_writer::ProgramWriter writer(options, [&](std::string_view piece) { file.write(piece); });
    gcode_writer::interpret_stepnc(read.project, args.input, stepnc, writer);
    file.commit();
    return 0;
  }

  interpreter::Options reading;
  reading.tools = options.tools;
  reading.subroutine_path = split_path(args.subroutine_path);
  interpreter::parse_dialect_name(args.dialect, reading.dialect);
  if (reading.dialect == interpreter::Dialect::Auto) {
    const auto detected = interpreter::detect_dialect_file(args.input);
    reading.dialect = detected.dialect;
    std::fprintf(stderr, "ncbridge: dialect %s (detected: %s)\n",
                 std::string(interpreter::dialect_name(detected.dialect)).c_str(), detected.reason.c_str());
  }
  if (args.heidenhain_feed_units == "mm/s") reading.heidenhain_feed_units = interpreter::Options::FeedUnits::PerSecond;

  step_writer::AtomicFile file(args.output);
  gcode_writer::ProgramWriter writer(options, [&](std::string_view piece) { file.write(piece); });
  interpreter::interpret_file(args.input, reading, writer);
  file.commit();
  return 0;
}

}  // namespace

void add_gcode_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<GcodeArguments>();
  CLI::App* cmd = app.add_subcommand(
      "gcode", "Write a program (any dialect) or a CC1 STEP-NC file as a program in a controller's dialect");
  cmd->add_option("input", args->input, "Part program, or a CC1 Part 21 file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--to", args->to, "Dialect to write")
      ->required()
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain"}));
  cmd->add_option("-o,--output", args->output, "Program file to write")->required();
  cmd->add_option("--dialect", args->dialect, "Dialect of the input program (auto: detect it and say which)")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain", "auto"}));
  cmd->add_option("--tool-table", args->tool_table, "LinuxCNC tool table (.tbl) the programs run with")
      ->check(CLI::ExistingFile);
  cmd->add_option("--tool-table-units", args->tool_table_units, "Units of the tool table values")
      ->check(CLI::IsMember({"mm", "inch"}));
  cmd->add_option("--tools", args->tools, "Tool list (JSON or YAML) the programs run with")->check(CLI::ExistingFile);
  cmd->add_option("--subroutine-path", args->subroutine_path, "Directories searched for called programs, ':'-separated");
  cmd->add_option("--heidenhain-feed-units", args->heidenhain_feed_units,
                  "Unit of the input's Heidenhain F words (mm/s for FreeCAD's Heidenhain post)")
      ->check(CLI::IsMember({"mm/min", "mm/s"}));
  cmd->add_option("--comments", args->comments,
                  "none; program: the input's comments (default); source: also name each source line or workingstep")
      ->check(CLI::IsMember({"none", "program", "source"}));
  cmd->add_option("--decimals", args->decimals, "Digits after the point for lengths in mm (one more in inches; default 4)")
      ->check(CLI::Range(0, 6));
  CLI::Option* numbers = cmd->add_flag("--block-numbers,!--no-block-numbers", args->block_numbers_flag,
                                       "Number the blocks N10, N20, ... (default: as the dialect's programs usually are)");
  cmd->add_option("--program-number", args->program_number, "Fanuc/Mach3 O number of the program (default 1000)")
      ->check(CLI::Range(1, 9999));
  cmd->add_option("--program-name", args->program_name, "Program name (default: the output file's name)");
  cmd->add_flag("--drop-path-tolerance", args->drop_path_tolerance,
                "Write LinuxCNC's G64 P tolerance as the dialect's plain continuous mode (it has no tolerance)");
  cmd->callback([args, numbers, &exit_code]() {
    if (numbers->count() > 0) args->block_numbers = args->block_numbers_flag;
    exit_code = run_gcode(*args);
  });
}

}  // namespace ncbridge::cli
