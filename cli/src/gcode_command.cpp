// `ncbridge gcode INPUT --to DIALECT -o OUT`: a program (any dialect the interpreter reads) or a
// CC1 STEP-NC file written as a program in one of the five dialects (docs/gcode.md). Embedded
// pipeline: interpreter (or the STEP-NC interpreter) -> gcode_writer, streamed into the run's
// output (output_files.hpp): every path checked before any work starts, and a failed run leaves
// no file (an old OUT as it was). INPUT "-" reads standard input, "-o -" writes standard output.
#include <CLI/CLI.hpp>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cc2_to_cc1.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "feedback.hpp"
#include "html_report.hpp"
#include "ncbridge/feature_recognizer/cc1_input.hpp"
#include "input_files.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/gcode_writer/program_writer.hpp"
#include "ncbridge/gcode_writer/stepnc_interpreter.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "output_files.hpp"

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
  std::string stock;
  std::string subroutine_path;
  std::string heidenhain_feed_units = "mm/min";
  bool strict = false;
  std::vector<int> machine_functions;
  std::string comments = "program";
  std::optional<int> decimals;
  std::optional<bool> block_numbers;
  bool block_numbers_flag = false;
  std::optional<std::uint32_t> program_number;
  std::string program_name;
  bool drop_path_tolerance = false;
  std::string html;
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
bool is_part21(const Input& input) {
  const std::string head = input_head(input, 8192);
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
// stem (the input's when writing to a stream) in capitals, letters, digits and _ only.
std::string name_from(const std::string& file_name) {
  std::string name;
  for (char c : std::filesystem::path(file_name).stem().string()) {
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

// Counts the calls for the progress line and the summary, on their way to the writer.
class CountingSink final : public canonical::Sink {
 public:
  CountingSink(canonical::Sink& next, Progress& progress) : next_(next), progress_(progress) {}
  void source_file(std::uint32_t index, std::string_view path) override { next_.source_file(index, path); }
  void call(const canonical::Call& call) override {
    ++calls_;
    progress_.tick([this] { return "writing: " + std::to_string(calls_) + " canonical calls"; });
    next_.call(call);
  }
  void end() override { next_.end(); }
  std::uint64_t calls() const { return calls_; }

 private:
  canonical::Sink& next_;
  Progress& progress_;
  std::uint64_t calls_ = 0;
};

int run_gcode(const GcodeArguments& args, const Feedback& feedback) {
  if (!args.tool_table.empty() && !args.tools.empty()) throw UsageError("--tool-table and --tools: give one tool list");
  if (!args.tool_table.empty()) require_input_file(args.tool_table, "--tool-table");
  if (!args.tools.empty()) require_input_file(args.tools, "--tools");
  if (!args.stock.empty()) require_input_file(args.stock, "--stock");
  OutputSet outputs;
  OutputFile& out = outputs.add(args.output, "-o");
  OutputFile* html = args.html.empty() ? nullptr : &outputs.add(args.html, "--html");
  for (const std::string* input : {&args.input, &args.tools, &args.tool_table, &args.stock}) outputs.protect(*input);
  const Input input = open_input(args.input, "program");
  if (html && !is_part21(input)) {
    throw UsageError("--html draws a STEP-NC input's toolpaths; for a program: ncbridge convert PROGRAM --level cc1 --html P.html");
  }

  gcode_writer::Options options;
  options.dialect = *gcode_writer::parse_dialect(args.to);
  options.tools = read_tools(args);
  if (!args.program_name.empty()) {
    options.program_name = args.program_name;
  } else {
    const std::string file = out.file_name();
    options.program_name = name_from(!file.empty() ? file : input.from_stdin() ? std::string() : input.path.string());
  }
  if (args.program_number) options.program_number = *args.program_number;
  options.decimals = args.decimals;
  options.block_numbers = args.block_numbers;
  options.drop_path_tolerance = args.drop_path_tolerance;
  options.comments = args.comments == "none"     ? gcode_writer::Comments::None
                     : args.comments == "source" ? gcode_writer::Comments::Source
                                                 : gcode_writer::Comments::Program;

  std::uint64_t lines = 0;
  auto write = [&](std::string_view piece) {
    for (char c : piece) lines += c == '\n';
    out.write(piece);
  };
  Progress progress(feedback.progress_wanted());
  std::uint64_t calls = 0;
  std::string what;
  if (is_part21(input)) {
    // a CC1 file: the STEP-NC interpreter's calls; the program runs with the file's tools
    // unless a tool list is given
    progress.set("reading " + input.name);
    auto read = input.text ? step_writer::read_stepnc(*input.text, input.name) : step_writer::read_stepnc_file(input.path);
    progress.stop();
    for (const auto& w : read.warnings) print_warning(w.where, w.message);
    std::optional<setup::Stock> stock;
    if (!args.stock.empty()) stock = setup::read_stock(args.stock);
    std::optional<stepnc::Project> cc2;  // the page lists a CC2 file's features
    std::vector<std::string> page_warnings;
    for (const auto& w : read.warnings) page_warnings.push_back(w.where.to_string() + ": " + w.message);
    if (needs_toolpaths(read.project)) {  // a CC2 file: its toolpaths generated first (docs/toolpaths.md)
      progress.set("generating toolpaths");
      std::vector<std::string> notes;
      if (html) cc2 = read.project;
      read.project = generate_cc1(read.project, stock, input.name, notes);
      progress.stop();
      for (const auto& n : notes) print_warning(SourceLocation{input.name, 0, 0}, n);
      for (const auto& n : notes) page_warnings.push_back(input.name + ": " + n);
    }
    if (html) {
      HtmlReportInput page;
      page.title = input.from_stdin() ? input.name : input.path.filename().string();
      page.level = "CC1";
      page.stock = feature_recognizer::stock_from_cc1(read.project);
      if (!page.stock) page.stock = stock;
      page.model = cc2 ? &*cc2 : &read.project;
      page.toolpaths = &read.project;
      page.warnings = page_warnings;
      html->write(html_report(page));
    }
    if (options.tools.empty()) options.tools = gcode_writer::stepnc_tools(read.project);
    gcode_writer::StepncOptions stepnc;
    if (options.comments == gcode_writer::Comments::Source) {
      stepnc.name_workingsteps = true;  // a workingstep's name says where its blocks come from
      options.comments = gcode_writer::Comments::Program;
    }
    gcode_writer::ProgramWriter writer(options, write);
    CountingSink sink(writer, progress);
    gcode_writer::interpret_stepnc(read.project, input.name, stepnc, sink);
    calls = sink.calls();
    what = "CC1 file";
  } else {
    interpreter::Options reading;
    reading.tools = options.tools;
    reading.subroutine_path = split_path(args.subroutine_path);
    interpreter::parse_dialect_name(args.dialect, reading.dialect);
    if (args.heidenhain_feed_units == "mm/s") reading.heidenhain_feed_units = interpreter::Options::FeedUnits::PerSecond;
    reading.strict = args.strict;
    reading.machine_functions = args.machine_functions;
    reading.warning = [&progress](const SourceLocation& where, const std::string& message) {
      progress.stop();
      print_warning(where, message);
    };
    if (reading.dialect == interpreter::Dialect::Auto) {
      // the dialect whose reading takes the whole program (errors are located InputErrors)
      const auto detected = input.text ? interpreter::detect_dialect_reading(*input.text, input.name, reading)
                                       : interpreter::detect_dialect_reading(input.path, reading);
      reading.dialect = detected.dialect;
      feedback.info("dialect " + std::string(interpreter::dialect_name(detected.dialect)) + " (detected: " +
                    detected.reason + ")");
    }
    gcode_writer::ProgramWriter writer(options, write);
    CountingSink sink(writer, progress);
    if (input.text) {
      interpreter::interpret_text(*input.text, input.name, reading, sink);
    } else {
      interpreter::interpret_file(input.path, reading, sink);
    }
    calls = sink.calls();
    what = std::string(interpreter::dialect_name(reading.dialect)) + " program";
  }
  progress.stop();
  outputs.commit();
  feedback.summary(out.display_name() + ": " + std::string(gcode_writer::dialect_name(options.dialect)) + ", " +
                   std::to_string(lines) + " lines from a " + what + " (" + std::to_string(calls) +
                   " canonical calls), " + std::to_string(static_cast<long long>(feedback.elapsed_s() * 1000 + 0.5)) +
                   " ms");
  return exit_status::ok;
}

}  // namespace

void add_gcode_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<GcodeArguments>();
  CLI::App* cmd = app.add_subcommand(
      "gcode", "Write a program (any dialect) or a CC1/CC2 STEP-NC file as a program in a controller's dialect");
  cmd->add_option("input", args->input,
                  "Part program, or a CC1 or CC2 Part 21 file (CC2: its toolpaths generated); - reads standard input")
      ->required();
  cmd->add_option("--to", args->to, "Dialect to write")
      ->required()
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain"}));
  cmd->add_option("-o,--output", args->output, "Program file to write; - writes standard output")->required();
  cmd->add_option("--dialect", args->dialect, "Dialect of the input program (auto: detect it and say which)")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain", "auto"}));
  cmd->add_option("--tool-table", args->tool_table, "LinuxCNC tool table (.tbl) the programs run with");
  cmd->add_option("--tool-table-units", args->tool_table_units, "Units of the tool table values")
      ->check(CLI::IsMember({"mm", "inch"}));
  cmd->add_option("--tools", args->tools, "Tool list (JSON or YAML) the programs run with");
  cmd->add_option("--stock", args->stock, "Stock block (JSON or YAML) a CC2 file without a rawpiece is cut from");
  cmd->add_option("--subroutine-path", args->subroutine_path, "Directories searched for called programs, ':'-separated");
  cmd->add_option("--heidenhain-feed-units", args->heidenhain_feed_units,
                  "Unit of the input's Heidenhain F words (mm/s for FreeCAD's Heidenhain post)")
      ->check(CLI::IsMember({"mm/min", "mm/s"}));
  cmd->add_flag("--strict", args->strict,
                "Refuse what is otherwise read with a warning (machine builder M codes, G43 without tool lengths)");
  cmd->add_option("--machine-functions", args->machine_functions,
                  "M codes that are the machine builder's machine functions (no motion), beyond the dialect's list")
      ->delimiter(',');
  cmd->add_option("--comments", args->comments,
                  "none; program: the input's comments (default); source: also name each source line or workingstep")
      ->check(CLI::IsMember({"none", "program", "source"}));
  cmd->add_option("--decimals", args->decimals, "Digits after the point for lengths in mm (one more in inches; default 4)")
      ->check(CLI::Range(0, 6));
  CLI::Option* numbers = cmd->add_flag("--block-numbers,!--no-block-numbers", args->block_numbers_flag,
                                       "Number the blocks N10, N20, ... (default: as the dialect's programs usually are)");
  cmd->add_option("--program-number", args->program_number, "Fanuc/Mach3 O number of the program (default 1000)")
      ->check(CLI::Range(1, 9999));
  cmd->add_option("--html", args->html, "Also write an HTML page of the toolpaths written (a STEP-NC input; docs/cli.md)");
  cmd->add_option("--program-name", args->program_name, "Program name (default: the output file's name)");
  cmd->add_flag("--drop-path-tolerance", args->drop_path_tolerance,
                "Write LinuxCNC's G64 P tolerance as the dialect's plain continuous mode (it has no tolerance)");
  cmd->callback([args, cmd, numbers, &exit_code]() {
    if (numbers->count() > 0) args->block_numbers = args->block_numbers_flag;
    exit_code = run_gcode(*args, Feedback(verbosity_of(*cmd)));
  });
}

}  // namespace ncbridge::cli
