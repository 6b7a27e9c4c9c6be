// `ncbridge convert PROGRAM --tools T --stock S -o OUT.stp [--report R.json]`: the embedded
// pipeline interpreter -> cc1_builder -> step_writer in one process. Every input and output path
// is checked before work starts, and the outputs (Part 21 file, report, page) appear together
// or not at all (output_files.hpp): a failed run leaves no file and old ones untouched. The
// program may be "-" (standard input), an output "-" (standard output). CC1 from a program is
// streamed: each workplan element is written (file and report) as soon as the builder finishes
// it, so memory stays flat; CC2 needs the whole CC1 model first.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cc1_report.hpp"
#include "cc2_output.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "html_report.hpp"
#include "input_files.hpp"
#include "output_files.hpp"
#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/part21_writer.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/step_writer/stepnc_stream_writer.hpp"

namespace ncbridge::cli {

namespace {

using Clock = std::chrono::steady_clock;

struct ConvertArguments {
  std::string program;
  std::string tools;
  std::string stock;
  std::string dialect = "rs274ngc";
  std::string heidenhain_feed_units = "mm/min";
  std::string level = "cc1";
  std::string output;
  std::string report;
  std::string html;
  std::string subroutine_path;
  std::optional<double> security_plane;
  bool strict = false;
};

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

interpreter::Dialect dialect_of(const std::string& name) {
  if (name == "fanuc") return interpreter::Dialect::Fanuc;
  if (name == "mach3") return interpreter::Dialect::Mach3;
  if (name == "siemens840d") return interpreter::Dialect::Siemens840D;
  if (name == "heidenhain") return interpreter::Dialect::Heidenhain;
  if (name == "auto") return interpreter::Dialect::Auto;
  return interpreter::Dialect::Rs274Ngc;
}

// Forwards the stream to the builder, timing the builder's share when a report wants it (two
// clock readings a call cost a few percent) and showing progress on a terminal.
class TimedSink final : public canonical::Sink {
 public:
  TimedSink(cc1_builder::Cc1Builder& builder, bool progress, bool timed)
      : builder_(builder), progress_(progress), timed_(timed) {}
  void source_file(std::uint32_t index, std::string_view path) override { builder_.source_file(index, path); }
  void call(const canonical::Call& c) override {
    if (timed_) {
      const auto start = Clock::now();
      builder_.call(c);
      spent_ += Clock::now() - start;
    } else {
      builder_.call(c);
    }
    if (progress_ && (++calls_ & 0xFFFF) == 0) {
      std::fprintf(stderr, "\rconverting: line %u, %llu canonical calls", c.source.line,
                   static_cast<unsigned long long>(calls_));
      std::fflush(stderr);
      shown_ = true;
    }
  }
  void end() override {
    const auto start = Clock::now();
    builder_.end();
    spent_ += Clock::now() - start;
    clear();
  }
  void clear() {
    if (shown_) std::fprintf(stderr, "\r\033[K");
    shown_ = false;
  }
  Clock::duration spent() const { return spent_; }

 private:
  cc1_builder::Cc1Builder& builder_;
  bool progress_, timed_;
  bool shown_ = false;
  std::uint64_t calls_ = 0;
  Clock::duration spent_{};
};

// Streamed CC1: each finished workplan element goes to the Part 21 writer and, timed, the report
// (the builder's clock runs around it too).
class ElementWriter final : public cc1_builder::WorkplanSink {
 public:
  ElementWriter(step_writer::StepncStreamWriter& writer, Cc1Report* report) : writer_(writer), report_(report) {}
  void element(const stepnc::Project& project, const stepnc::Executable& element) override {
    if (!report_) {
      writer_.element(project, element);
      return;
    }
    const auto start = Clock::now();
    writer_.element(project, element);
    report_->element(project, element);
    spent_ += Clock::now() - start;
  }
  Clock::duration spent() const { return spent_; }

 private:
  step_writer::StepncStreamWriter& writer_;
  Cc1Report* report_;
  Clock::duration spent_{};
};

std::string_view kind_of(const stepnc::Executable& e) {
  return std::holds_alternative<stepnc::RapidMovement>(e) ? "RAPID_MOVEMENT" : "MACHINING_WORKINGSTEP";
}

nlohmann::ordered_json report_of(const ConvertArguments& args, const std::string& program, const stepnc::Project& p,
                         const std::vector<cc1_builder::Warning>& warnings, std::uint64_t calls,
                         std::size_t bytes, const nlohmann::ordered_json& timings) {
  using json = nlohmann::ordered_json;
  json workingsteps = json::array();
  for (const auto& e : p.main_workplan.its_elements) {
    json w;
    w["kind"] = kind_of(e);
    std::visit([&](const auto& x) {
      w["id"] = x.its_id;
      if (x.source.first_line != 0) w["lines"] = {x.source.first_line, x.source.last_line};
    }, e);
    if (const auto* ws = std::get_if<stepnc::MachiningWorkingstep>(&e)) {
      const auto& op = p.operation(ws->its_operation);
      const auto& mop = stepnc::machining_operation(op);
      w["operation"] = stepnc::entity_name(op);
      w["feature"] = stepnc::feature_id(p.feature(ws->its_feature));
      w["tool"] = p.tool(mop.its_tool).its_id;
      const auto& t = p.technology(mop.its_technology);
      if (t.feedrate) w["feedrate_m_per_s"] = *t.feedrate;
      if (t.spindle) w["spindle_rev_per_s"] = *t.spindle;
    }
    workingsteps.push_back(std::move(w));
  }
  json tools = json::array();
  for (const auto& t : p.tools) {
    tools.push_back({{"number", t.number}, {"id", t.its_id}, {"diameter_mm", t.dimension.diameter}});
  }
  json features = json::array();
  for (const auto& f : p.features) features.push_back({{"id", stepnc::feature_id(f)}, {"type", stepnc::entity_name(f)}});
  json warning_list = json::array();
  for (const auto& w : warnings) warning_list.push_back({{"where", w.where.to_string()}, {"message", w.message}});
  return json{{"program", program},
              {"output", args.output},
              {"level", args.level},
              {"canonical_calls", calls},
              {"output_bytes", bytes},
              {"workingsteps", workingsteps},
              {"tools", tools},
              {"features", features},
              {"warnings", warning_list},
              {"timings_ms", timings}};
}

// A Part 21 file (a CC1 file to raise to CC2) rather than a program: it opens with
// ISO-10303-21; after any white space and /* comments */.
bool is_part21_file(const Input& input) {
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

// What is open before any work starts: the program, and every output checked.
struct ConvertRun {
  Input program;
  OutputSet outputs;
  OutputFile* stp = nullptr;
  OutputFile* report = nullptr;
  OutputFile* html = nullptr;
};

// The Part 21 FILE_NAME.name: the output's file name, or the program's for standard output.
std::string part21_file_name(const ConvertRun& run) {
  std::string name = run.stp->file_name();
  if (name.empty()) name = run.program.from_stdin() ? "stdin.stp" : run.program.path.stem().string() + ".stp";
  return name;
}

cc1_builder::Options builder_options(const ConvertArguments& args, const std::optional<setup::Stock>& stock) {
  cc1_builder::Options options;
  options.tools = setup::read_tool_list(args.tools);
  options.stock = *stock;
  options.security_plane_z = args.security_plane;
  return options;
}

// The interpreter's warnings (collected in `read`) before the builder's: they come from reading
// the program.
std::vector<cc1_builder::Warning> all_warnings(const std::vector<cc1_builder::Warning>& read,
                                               const std::vector<cc1_builder::Warning>& built) {
  std::vector<cc1_builder::Warning> all = read;
  all.insert(all.end(), built.begin(), built.end());
  return all;
}

interpreter::Options interpreter_options(const ConvertArguments& args, const Input& program, const setup::ToolList& tools,
                                         std::vector<cc1_builder::Warning>& warnings) {
  interpreter::Options interp;
  interp.strict = args.strict;
  interp.warning = [&warnings](const SourceLocation& where, const std::string& message) {
    warnings.push_back({where, message});
  };
  interp.dialect = dialect_of(args.dialect);
  if (interp.dialect == interpreter::Dialect::Auto) {  // detect, and say which
    const auto detected = program.text ? interpreter::detect_dialect(*program.text)
                                       : interpreter::detect_dialect_file(program.path);
    interp.dialect = detected.dialect;
    std::fprintf(stderr, "ncbridge: dialect %s (detected: %s)\n",
                 std::string(interpreter::dialect_name(detected.dialect)).c_str(), detected.reason.c_str());
  }
  if (args.heidenhain_feed_units == "mm/s") interp.heidenhain_feed_units = interpreter::Options::FeedUnits::PerSecond;
  interp.tools = tools;
  std::stringstream dirs(args.subroutine_path);
  for (std::string d; std::getline(dirs, d, ':');) {
    if (!d.empty()) interp.subroutine_path.emplace_back(d);
  }
  return interp;
}

void interpret(const Input& program, const interpreter::Options& interp, TimedSink& sink) {
  try {
    if (program.text) {
      interpreter::interpret_text(*program.text, program.name, interp, sink);
    } else {
      interpreter::interpret_file(program.path, interp, sink);
    }
  } catch (...) {
    sink.clear();
    throw;
  }
}

void print_warnings(const std::vector<cc1_builder::Warning>& warnings) {
  for (const auto& w : warnings) print_warning(w.where, w.message);
}

// CC1 from a program, streamed: interpreter -> cc1_builder -> (Part 21 writer, report) element
// by element; the model is never whole in memory.
int run_streamed_cc1(const ConvertArguments& args, ConvertRun& run, Clock::time_point t0) {
  const std::optional<setup::Stock> stock = setup::read_stock(args.stock);
  const cc1_builder::Options options = builder_options(args, stock);
  std::vector<cc1_builder::Warning> read_warnings;
  const interpreter::Options interp = interpreter_options(args, run.program, options.tools, read_warnings);

  step_writer::StepncWriteOptions write;
  write.file_name = part21_file_name(run);
  step_writer::StepncStreamWriter writer(write, [&](std::string_view chunk) { run.stp->write(chunk); });
  std::optional<Cc1Report> report;
  if (run.report) report.emplace(*run.report, Cc1Report::Head{run.program.name, args.output, args.level});
  ElementWriter elements(writer, report ? &*report : nullptr);
  cc1_builder::Cc1Builder builder(options, &elements);
  TimedSink sink(builder, isatty(STDERR_FILENO) != 0, report.has_value());
  const auto t_interpret = Clock::now();
  interpret(run.program, interp, sink);
  const auto t_built = Clock::now();
  const stepnc::Project project = builder.take_project();
  const std::uint64_t bytes = writer.finish(project);
  const auto t_written = Clock::now();

  const std::vector<cc1_builder::Warning> warnings = all_warnings(read_warnings, builder.warnings());
  if (report) {
    // The writer's and the report's work happens inside the builder's calls; each is counted
    // once, under step_writer. "output" is the report's last part, the syncs and renames.
    const double written_ms = ms(elements.spent()) + ms(t_written - t_built);
    Cc1Report::Tail tail;
    tail.canonical_calls = builder.calls_seen();
    tail.output_bytes = bytes;
    for (const auto& w : warnings) tail.warnings.emplace_back(w.where.to_string(), w.message);
    tail.timings_ms = {{"read_inputs", ms(t_interpret - t0)},
                       {"interpreter", ms(t_built - t_interpret) - ms(sink.spent())},
                       {"cc1_builder", ms(sink.spent()) - ms(elements.spent())},
                       {"step_writer", written_ms},
                       {"output", ms(Clock::now() - t_written)},
                       {"total", ms(Clock::now() - t0)}};
    report->finish(project, tail);
  }
  run.outputs.commit();
  print_warnings(warnings);
  return 0;
}

// Every path checked and the program read (standard input) before any work starts.
ConvertRun open_run(const ConvertArguments& args) {
  ConvertRun run;
  if (!args.html.empty() && args.level != "cc2") {
    throw UsageError("--html needs --level cc2 (it draws the recognised features)");
  }
  if (!args.tools.empty()) require_input_file(args.tools, "--tools");
  if (!args.stock.empty()) require_input_file(args.stock, "--stock");
  run.stp = &run.outputs.add(args.output, "-o");
  if (!args.report.empty()) run.report = &run.outputs.add(args.report, "--report");
  if (!args.html.empty()) run.html = &run.outputs.add(args.html, "--html");
  for (const std::string* input : {&args.program, &args.tools, &args.stock}) run.outputs.protect(*input);
  run.program = open_input(args.program, "program");
  return run;
}

int run_convert(const ConvertArguments& args) {
  const auto t0 = Clock::now();
  ConvertRun run = open_run(args);
  const bool part21_input = is_part21_file(run.program);
  if (!part21_input && (args.tools.empty() || args.stock.empty())) {
    throw UsageError("converting a program needs --tools and --stock");
  }
  if (!part21_input && args.level == "cc1") return run_streamed_cc1(args, run, t0);
  std::vector<cc1_builder::Warning> warnings;
  std::uint64_t calls = 0;
  stepnc::Project project;
  std::optional<setup::Stock> stock;
  if (!args.stock.empty()) stock = setup::read_stock(args.stock);
  Clock::time_point t_interpret, t_built;
  Clock::duration builder_spent{};
  if (part21_input) {  // the CC1 model read back: everything recognition uses is in the file
    t_interpret = Clock::now();
    auto read = run.program.text ? step_writer::read_stepnc(*run.program.text, run.program.name)
                                 : step_writer::read_stepnc_file(run.program.path);
    for (const auto& d : read.warnings) warnings.push_back({d.where, d.message});
    project = std::move(read.project);
    t_built = Clock::now();
  } else {
    const cc1_builder::Options options = builder_options(args, stock);
    std::vector<cc1_builder::Warning> read_warnings;
    const interpreter::Options interp = interpreter_options(args, run.program, options.tools, read_warnings);
    cc1_builder::Cc1Builder builder(options);
    TimedSink sink(builder, isatty(STDERR_FILENO) != 0, !args.report.empty());
    t_interpret = Clock::now();
    interpret(run.program, interp, sink);
    t_built = Clock::now();
    warnings = all_warnings(read_warnings, builder.warnings());
    calls = builder.calls_seen();
    project = builder.take_project();
    builder_spent = sink.spent();
  }
  // CC2: the features recognised in the CC1 model, with their workingsteps (cc2_output.hpp).
  std::optional<Cc2Output> cc2;
  if (args.level == "cc2") cc2 = build_cc2(project, stock, run.program.name);
  const auto t_recognized = Clock::now();

  step_writer::StepncWriteOptions write;
  write.file_name = part21_file_name(run);
  if (cc2) write.description = {"ISO 14649 CC2 program written by ncbridge"};
  // The text streams into the temporary file as it is made.
  const std::uint64_t bytes =
      step_writer::write_stepnc(cc2 ? cc2->project : project, write, [&](std::string_view chunk) { run.stp->write(chunk); });
  const auto t_written = Clock::now();

  if (cc2) {
    for (const auto& w : cc2->warnings) {
      cc1_builder::Warning warning;
      warning.where.file = run.program.name;
      warning.message = w;
      warnings.push_back(std::move(warning));
    }
  }
  if (run.report) {
    const double builder_ms = ms(builder_spent);
    nlohmann::ordered_json timings{{"read_inputs", ms(t_interpret - t0)},
                                 {"interpreter", ms(t_built - t_interpret) - builder_ms},
                                 {"cc1_builder", builder_ms}};
    if (cc2) timings["feature_recognizer"] = ms(t_recognized - t_built);
    timings["step_writer"] = ms(t_written - t_recognized);
    timings["output"] = ms(Clock::now() - t_written);
    timings["total"] = ms(Clock::now() - t0);
    auto report = report_of(args, run.program.name, cc2 ? cc2->project : project, warnings, calls, bytes, timings);
    if (cc2) report["features"] = cc2_features_json(*cc2);
    run.report->write(report.dump(2) + "\n");
  }
  if (run.html) {
    HtmlReportInput page;
    page.title = run.program.from_stdin() ? run.program.name : run.program.path.filename().string();
    page.cc2 = &*cc2;
    for (const auto& w : warnings) page.warnings.push_back(w.where.to_string() + ": " + w.message);
    run.html->write(html_report(page));
  }
  run.outputs.commit();
  print_warnings(warnings);
  return 0;
}

}  // namespace

void add_convert_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ConvertArguments>();
  CLI::App* cmd = app.add_subcommand("convert", "Convert a part program into an ISO 14649 (STEP-NC) Part 21 file");
  cmd->add_option("program", args->program, "Part program, or a CC1 Part 21 file to raise to --level cc2; - reads standard input")->required();
  cmd->add_option("--tools", args->tools, "Tool list (JSON or YAML, docs/formats/tools.md); needed for a program");
  cmd->add_option("--stock", args->stock, "Stock block (JSON or YAML, docs/formats/stock.md); needed for a program");
  cmd->add_option("--dialect", args->dialect, "Program dialect")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain", "auto"}));
  cmd->add_option("--heidenhain-feed-units", args->heidenhain_feed_units,
                  "Unit of Heidenhain F words (mm/s for FreeCAD's Heidenhain post; never guessed)")
      ->check(CLI::IsMember({"mm/min", "mm/s"}));
  cmd->add_option("--level", args->level, "Conformance class of the output")->check(CLI::IsMember({"cc1", "cc2"}));
  cmd->add_option("-o,--output", args->output, "Part 21 file to write; - writes standard output")->required();
  cmd->add_option("--report", args->report, "Also write a JSON report (docs/formats/report.md)");
  cmd->add_option("--html", args->html, "Also write an HTML page: top view, toolpaths, features (--level cc2)");
  cmd->add_option("--security-plane", args->security_plane, "Security plane Z in mm (default: the highest rapid)");
  cmd->add_option("--subroutine-path", args->subroutine_path, "Directories searched for o<name> call files, ':'-separated");
  cmd->add_flag("--strict", args->strict,
                "Refuse what is otherwise read with a warning (machine builder M codes, G43 without tool lengths)");
  cmd->callback([args, &exit_code]() { exit_code = run_convert(*args); });
}

}  // namespace ncbridge::cli
