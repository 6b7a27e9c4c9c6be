// `ncbridge convert PROGRAM --tools T --stock S -o OUT.stp [--report R.json]`: the embedded
// pipeline interpreter -> cc1_builder -> step_writer in one process. Every input and output path
// is checked before work starts, and the outputs (Part 21 file, report, page) appear together
// or not at all (output_files.hpp): a failed run leaves no file and old ones untouched. The
// program may be "-" (standard input), an output "-" (standard output). CC1 from a program is
// streamed: each workplan element is written (file and report) as soon as the builder finishes
// it, so memory stays flat; CC2 needs the whole CC1 model first.
#include <CLI/CLI.hpp>

#include <cctype>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cc1_report.hpp"
#include "cc2_output.hpp"
#include "cc2_to_cc1.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "feedback.hpp"
#include "html_report.hpp"
#include "input_files.hpp"
#include "output_files.hpp"
#include "tool_source.hpp"
#include "setup_checks.hpp"
#include "warning.hpp"
#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/common/version.hpp"
#include "ncbridge/feature_recognizer/cc1_input.hpp"
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
  ToolSource tools;
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
  std::vector<int> machine_functions;
  double max_seconds = 0;  // 0: no limit
};

// Throws once the conversion has run longer than --max-seconds (an InputError: the program is
// too costly to convert within the bound).
class TimeLimit {
 public:
  TimeLimit(const ConvertArguments& args, Clock::time_point start) : program_(args.program), seconds_(args.max_seconds) {
    if (seconds_ > 0) deadline_ = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds_));
  }
  void check() const {
    if (!deadline_ || Clock::now() <= *deadline_) return;
    char text[32];
    std::snprintf(text, sizeof text, "%g", seconds_);
    throw InputError({program_, 1, 1}, std::string("the conversion ran longer than --max-seconds (") + text +
                                           " s) and was stopped; nothing was written");
  }
  bool set() const { return deadline_.has_value(); }

 private:
  std::string program_;
  double seconds_;
  std::optional<Clock::time_point> deadline_;
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
// clock readings a call cost a few percent), telling the setup checks what only the stream
// says, and feeding the progress line.
class TimedSink final : public canonical::Sink {
 public:
  TimedSink(cc1_builder::Cc1Builder& builder, ProgramFacts& facts, Progress& progress, bool timed, const TimeLimit& limit)
      : builder_(builder), facts_(facts), progress_(progress), timed_(timed), limit_(limit) {}
  void source_file(std::uint32_t index, std::string_view path) override {
    facts_.source_file(index, path);
    builder_.source_file(index, path);
  }
  void call(const canonical::Call& c) override {
    facts_.call(c);
    if (timed_) {
      const auto start = Clock::now();
      builder_.call(c);
      spent_ += Clock::now() - start;
    } else {
      builder_.call(c);
    }
    if ((++calls_ & 0xFFF) == 0) limit_.check();
    progress_.tick([&] {
      return "converting: line " + std::to_string(c.source.line) + ", " + std::to_string(builder_.calls_seen()) +
             " canonical calls";
    });
  }
  void end() override {
    const auto start = Clock::now();
    builder_.end();
    spent_ += Clock::now() - start;
  }
  Clock::duration spent() const { return spent_; }

 private:
  cc1_builder::Cc1Builder& builder_;
  ProgramFacts& facts_;
  Progress& progress_;
  bool timed_;
  const TimeLimit& limit_;
  std::uint64_t calls_ = 0;
  Clock::duration spent_{};
};

// Streamed CC1: each finished workplan element goes to the setup checks, the Part 21 writer
// and, timed, the report (the builder's clock runs around it too).
class ElementWriter final : public cc1_builder::WorkplanSink {
 public:
  ElementWriter(step_writer::StepncStreamWriter& writer, Cc1Report* report, SetupChecks& checks)
      : writer_(writer), report_(report), checks_(checks) {}
  void element(const stepnc::Project& project, const stepnc::Executable& element) override {
    checks_.element(project, element);
    workingsteps_ += std::holds_alternative<stepnc::MachiningWorkingstep>(element);
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
  std::size_t workingsteps() const { return workingsteps_; }

 private:
  step_writer::StepncStreamWriter& writer_;
  Cc1Report* report_;
  SetupChecks& checks_;
  std::size_t workingsteps_ = 0;
  Clock::duration spent_{};
};

std::string_view kind_of(const stepnc::Executable& e) {
  if (std::holds_alternative<stepnc::RapidMovement>(e)) return "RAPID_MOVEMENT";
  if (std::holds_alternative<stepnc::WorkpieceProbing>(e)) return "WORKPIECE_PROBING";
  return "MACHINING_WORKINGSTEP";
}

nlohmann::ordered_json report_of(const ConvertArguments& args, const std::string& program, const stepnc::Project& p,
                         const std::vector<Warning>& warnings, std::uint64_t calls,
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
  for (const auto& w : warnings) {
    warning_list.push_back({{"kind", w.kind}, {"where", w.where.to_string()}, {"message", w.message}});
  }
  return json{{"ncbridge_version", std::string(version())},
              {"program", program},
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
  Feedback feedback{Verbosity::Normal};
  std::unique_ptr<Progress> progress;
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
  options.tools = args.tools.read();
  options.stock = *stock;
  options.security_plane_z = args.security_plane;
  return options;
}

// The interpreter's warnings go to `warnings` (kind "reading"): what it read although the
// controller's data is missing or the construct has no motion of its own. --strict makes the
// interpreter refuse them itself, at their place in the program.
interpreter::Options interpreter_options(const ConvertArguments& args, const ConvertRun& run, const setup::ToolList& tools,
                                         std::vector<Warning>& warnings) {
  const Input& program = run.program;
  interpreter::Options interp;
  interp.strict = args.strict;
  // a program that ends without M2/M30 (or %, END PGM) runs to its last block on the control:
  // converted, with a warning (refused under --strict)
  interp.require_program_end = false;
  interp.machine_functions = args.machine_functions;
  interp.warning = [&warnings](const SourceLocation& where, const std::string& message) {
    Warning w;
    w.kind = "reading";
    w.where = where;
    w.message = message;
    warnings.push_back(std::move(w));
  };
  interp.dialect = dialect_of(args.dialect);
  if (args.heidenhain_feed_units == "mm/s") interp.heidenhain_feed_units = interpreter::Options::FeedUnits::PerSecond;
  interp.tools = tools;
  std::stringstream dirs(args.subroutine_path);
  for (std::string d; std::getline(dirs, d, ':');) {
    if (!d.empty()) interp.subroutine_path.emplace_back(d);
  }
  if (interp.dialect == interpreter::Dialect::Auto) {  // detect (the reading that takes the whole program), and say which
    const auto detected = program.text ? interpreter::detect_dialect_reading(*program.text, program.name, interp)
                                       : interpreter::detect_dialect_reading(program.path, interp);
    interp.dialect = detected.dialect;
    run.feedback.info("dialect " + std::string(interpreter::dialect_name(detected.dialect)) + " (detected: " + detected.reason + ")");
  }
  return interp;
}

void interpret(const Input& program, const interpreter::Options& interp, TimedSink& sink) {
  if (program.text) {
    interpreter::interpret_text(*program.text, program.name, interp, sink);
  } else {
    interpreter::interpret_file(program.path, interp, sink);
  }
}

std::string setup_detail(const cc1_builder::Options& options, const ConvertArguments& args) {
  std::string text = "read " + std::to_string(options.tools.tools().size()) + " tools from " + args.tools.file();
  if (options.stock) {
    const auto& s = *options.stock;
    char box[160];
    std::snprintf(box, sizeof box, "; stock %g x %g x %g mm (X%g..%g Y%g..%g Z%g..%g) from ", s.size(0), s.size(1), s.size(2),
                  s.min[0], s.max[0], s.min[1], s.max[1], s.min[2], s.max[2]);
    text += box + args.stock;
  }
  return text;
}

std::string seconds(double s) {
  char text[32];
  if (s < 1) std::snprintf(text, sizeof text, "%.0f ms", s * 1000);
  else std::snprintf(text, sizeof text, "%.2f s", s);
  return text;
}

std::string count(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

void print_warnings(const std::vector<Warning>& warnings) {
  for (const auto& w : warnings) print_warning(w.where, w.message + " [" + w.kind + "]");
}

// After the outputs appeared: the warnings, the one-line summary, and with -v what was written.
void finish_run(ConvertRun& run, const ConvertArguments& args, const std::vector<Warning>& warnings,
                const std::string& contents, std::uint64_t bytes) {
  run.progress->stop();
  print_warnings(warnings);
  run.feedback.detail("wrote " + run.stp->display_name() + " (" + std::to_string(bytes) + " bytes)" +
                      (run.report ? ", " + run.report->display_name() : "") + (run.html ? ", " + run.html->display_name() : ""));
  run.feedback.summary(run.stp->display_name() + ": " + (args.level == "cc2" ? "CC2, " : "CC1, ") + contents + ", " +
                       count(warnings.size(), "warning", "warnings") + ", " + seconds(run.feedback.elapsed_s()));
}

SetupCheckInputs check_inputs(const ConvertArguments& args, const Input& program, const std::optional<setup::Stock>& stock,
                              const setup::ToolList* tools) {
  SetupCheckInputs in;
  in.program = program.name;
  in.stock = stock;
  in.stock_file = args.stock;
  in.tools = tools;
  in.tools_file = args.tools.file();
  in.security_plane = args.security_plane;
  in.heidenhain_per_minute = (args.dialect == "heidenhain" || args.dialect == "auto") && args.heidenhain_feed_units == "mm/min";
  return in;
}

// The setup checks' warnings first (they say the result may be wrong), then the
// interpreter's (from reading the program), then the builder's.
std::vector<Warning> all_warnings(const SetupChecks& checks, const std::vector<Warning>& read,
                                  const std::vector<cc1_builder::Warning>& builder) {
  std::vector<Warning> all = checks.warnings();
  all.insert(all.end(), read.begin(), read.end());
  for (const auto& w : builder) {
    Warning warning;
    warning.kind = "representation";
    warning.where = w.where;
    warning.message = w.message;
    all.push_back(std::move(warning));
  }
  return all;
}

// --strict: a warning is an error; nothing is written (the outputs are not committed).
void refuse_warnings_if_strict(const ConvertArguments& args, const std::vector<Warning>& warnings, Progress& progress) {
  if (!args.strict || warnings.empty()) return;
  progress.stop();
  for (const auto& w : warnings) print_error(w.where, w.message + " [" + w.kind + "]");
  throw InputError({}, std::to_string(warnings.size()) + (warnings.size() == 1 ? " warning" : " warnings") +
                           " with --strict: nothing written");
}


// CC1 from a program, streamed: interpreter -> cc1_builder -> (Part 21 writer, report) element
// by element; the model is never whole in memory.
int run_streamed_cc1(const ConvertArguments& args, ConvertRun& run, Clock::time_point t0) {
  const TimeLimit limit(args, t0);
  const std::optional<setup::Stock> stock = setup::read_stock(args.stock);
  const cc1_builder::Options options = builder_options(args, stock);
  run.feedback.detail(setup_detail(options, args));
  std::vector<Warning> read_warnings;
  const interpreter::Options interp = interpreter_options(args, run, options.tools, read_warnings);

  step_writer::StepncWriteOptions write;
  write.file_name = part21_file_name(run);
  step_writer::StepncStreamWriter writer(write, [&](std::string_view chunk) { run.stp->write(chunk); });
  std::optional<Cc1Report> report;
  if (run.report) report.emplace(*run.report, Cc1Report::Head{run.program.name, args.output, args.level});
  ProgramFacts facts;
  SetupChecks checks(check_inputs(args, run.program, stock, &options.tools), &facts);
  ElementWriter elements(writer, report ? &*report : nullptr, checks);
  cc1_builder::Cc1Builder builder(options, &elements);
  TimedSink sink(builder, facts, *run.progress, report.has_value(), limit);
  const auto t_interpret = Clock::now();
  interpret(run.program, interp, sink);
  const auto t_built = Clock::now();
  run.feedback.detail("interpreted and built " + count(builder.calls_seen(), "canonical call", "canonical calls") + " in " +
                      seconds(ms(t_built - t_interpret) / 1000));
  const stepnc::Project project = builder.take_project();
  checks.finish(project);
  const std::vector<Warning> warnings = all_warnings(checks, read_warnings, builder.warnings());
  refuse_warnings_if_strict(args, warnings, *run.progress);
  const std::uint64_t bytes = writer.finish(project);
  const auto t_written = Clock::now();

  if (report) {
    // The writer's and the report's work happens inside the builder's calls; each is counted
    // once, under step_writer. "output" is the report's last part, the syncs and renames.
    const double written_ms = ms(elements.spent()) + ms(t_written - t_built);
    Cc1Report::Tail tail;
    tail.canonical_calls = builder.calls_seen();
    tail.output_bytes = bytes;
    tail.warnings = warnings;
    tail.timings_ms = {{"read_inputs", ms(t_interpret - t0)},
                       {"interpreter", ms(t_built - t_interpret) - ms(sink.spent())},
                       {"cc1_builder", ms(sink.spent()) - ms(elements.spent())},
                       {"step_writer", written_ms},
                       {"output", ms(Clock::now() - t_written)},
                       {"total", ms(Clock::now() - t0)}};
    report->finish(project, tail);
  }
  run.outputs.commit();
  finish_run(run, args, warnings,
             count(elements.workingsteps(), "workingstep", "workingsteps") + ", " + count(project.tools.size(), "tool", "tools"),
             bytes);
  return 0;
}

// Every path checked and the program read (standard input) before any work starts.
ConvertRun open_run(const ConvertArguments& args, Verbosity verbosity) {
  ConvertRun run;
  run.feedback = Feedback(verbosity);
  if (args.security_plane && !std::isfinite(*args.security_plane)) throw UsageError("--security-plane must be a number");
  args.tools.check();
  if (!args.stock.empty()) require_input_file(args.stock, "--stock");
  run.stp = &run.outputs.add(args.output, "-o");
  if (!args.report.empty()) run.report = &run.outputs.add(args.report, "--report");
  if (!args.html.empty()) run.html = &run.outputs.add(args.html, "--html");
  for (const std::string* input : {&args.program, &args.tools.file(), &args.stock}) run.outputs.protect(*input);
  run.program = open_input(args.program, "program");
  run.progress = std::make_unique<Progress>(run.feedback.progress_wanted());
  return run;
}

int run_convert(const ConvertArguments& args, Verbosity verbosity) {
  const auto t0 = Clock::now();
  ConvertRun run = open_run(args, verbosity);
  const TimeLimit limit(args, t0);
  const bool part21_input = is_part21_file(run.program);
  if (!part21_input && (!args.tools.given() || args.stock.empty())) {
    throw UsageError("converting a program needs --tools (or --tool-table) and --stock");
  }
  // The page draws the whole model: a program's CC1 model is then built whole, not streamed.
  if (!part21_input && args.level == "cc1" && !run.html) return run_streamed_cc1(args, run, t0);
  std::vector<Warning> warnings;
  std::uint64_t calls = 0;
  stepnc::Project project;
  std::optional<stepnc::Project> cc2_input;  // a CC2 file given toolpaths, for the page
  std::optional<setup::Stock> stock;
  if (!args.stock.empty()) stock = setup::read_stock(args.stock);
  Clock::time_point t_interpret, t_built;
  Clock::duration builder_spent{};
  if (part21_input) {  // the CC1 model read back: everything recognition uses is in the file
    t_interpret = Clock::now();
    auto read = run.program.text ? step_writer::read_stepnc(*run.program.text, run.program.name)
                                 : step_writer::read_stepnc_file(run.program.path);
    for (const auto& d : read.warnings) warnings.push_back({"input", d.where, d.message});
    project = std::move(read.project);
    if (args.level == "cc1" && needs_toolpaths(project)) {  // CC2 in: generate the toolpaths
      std::vector<std::string> notes;
      if (run.html) cc2_input = project;  // the page lists its features
      project = generate_cc1(project, stock, run.program.name, notes);
      for (auto& n : notes) warnings.push_back({"generation", {run.program.name, 0, 0}, std::move(n)});
    }
    t_built = Clock::now();
    SetupChecks checks(check_inputs(args, run.program, stock, nullptr), nullptr);
    for (const auto& e : project.main_workplan.its_elements) checks.element(project, e);
    checks.finish(project);
    warnings.insert(warnings.begin(), checks.warnings().begin(), checks.warnings().end());
  } else {
    const cc1_builder::Options options = builder_options(args, stock);
    run.feedback.detail(setup_detail(options, args));
    std::vector<Warning> read_warnings;
    const interpreter::Options interp = interpreter_options(args, run, options.tools, read_warnings);
    cc1_builder::Cc1Builder builder(options);
    ProgramFacts facts;
    TimedSink sink(builder, facts, *run.progress, !args.report.empty(), limit);
    t_interpret = Clock::now();
    interpret(run.program, interp, sink);
    t_built = Clock::now();
    run.feedback.detail("interpreted and built " + count(builder.calls_seen(), "canonical call", "canonical calls") + " in " +
                        seconds(ms(t_built - t_interpret) / 1000));
    calls = builder.calls_seen();
    project = builder.take_project();
    builder_spent = sink.spent();
    SetupChecks checks(check_inputs(args, run.program, stock, &options.tools), &facts);
    for (const auto& e : project.main_workplan.its_elements) checks.element(project, e);
    checks.finish(project);
    warnings = all_warnings(checks, read_warnings, builder.warnings());
  }
  // CC2: the features recognised in the CC1 model, with their workingsteps (cc2_output.hpp).
  std::optional<Cc2Output> cc2;
  if (args.level == "cc2") {
    run.progress->set("recognising features");
    std::function<void()> checkpoint;
    if (limit.set()) checkpoint = [&limit] { limit.check(); };
    cc2 = build_cc2(project, stock, run.program.name, checkpoint);
    run.feedback.detail("recognised " + count(cc2->features.size(), "feature", "features") + " in " +
                        seconds(ms(Clock::now() - t_built) / 1000));
  }
  const auto t_recognized = Clock::now();
  run.progress->set("writing " + run.stp->display_name());

  step_writer::StepncWriteOptions write;
  write.file_name = part21_file_name(run);
  if (cc2) write.description = {"ISO 14649 CC2 program written by ncbridge"};
  // The text streams into the temporary file as it is made.
  const std::uint64_t bytes =
      step_writer::write_stepnc(cc2 ? cc2->project : project, write, [&](std::string_view chunk) { run.stp->write(chunk); });
  const auto t_written = Clock::now();

  if (cc2) {
    for (const auto& message : cc2->warnings) {
      Warning w;
      w.kind = "recognition";
      w.where.file = run.program.name;
      w.message = message;
      warnings.push_back(std::move(w));
    }
  }
  refuse_warnings_if_strict(args, warnings, *run.progress);
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
    if (cc2) {
      page.stock = cc2->stock;
      page.model = &cc2->project;
    } else {
      page.level = "CC1";
      page.stock = feature_recognizer::stock_from_cc1(project);
      if (!page.stock) page.stock = stock;
      page.model = cc2_input ? &*cc2_input : &project;
      page.toolpaths = &project;
    }
    for (const auto& w : warnings) {
      const bool setup = w.kind != "representation" && w.kind != "recognition" && w.kind != "input";
      (setup ? page.setup_warnings : page.warnings).push_back(w.where.to_string() + ": " + w.message);
    }
    run.html->write(html_report(page));
  }
  run.outputs.commit();
  const stepnc::Project& written = cc2 ? cc2->project : project;
  std::size_t workingsteps = 0;
  for (const auto& e : written.main_workplan.its_elements) workingsteps += std::holds_alternative<stepnc::MachiningWorkingstep>(e);
  finish_run(run, args, warnings,
             (cc2 ? count(cc2->features.size(), "feature", "features") + ", " : std::string()) +
                 count(workingsteps, "workingstep", "workingsteps") + ", " + count(written.tools.size(), "tool", "tools"),
             bytes);
  return 0;
}

}  // namespace

void add_convert_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ConvertArguments>();
  CLI::App* cmd = app.add_subcommand("convert", "Convert a part program into an ISO 14649 (STEP-NC) Part 21 file");
  cmd->add_option("program", args->program, "Part program, a CC1 Part 21 file to raise to --level cc2, or a CC2 file to give toolpaths (--level cc1); - reads standard input")->required();
  add_tool_source_options(*cmd, args->tools, "; needed for a program");
  cmd->add_option("--stock", args->stock, "Stock block (JSON or YAML, docs/formats/stock.md); needed for a program");
  cmd->add_option("--dialect", args->dialect, "Program dialect")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain", "auto"}));
  cmd->add_option("--heidenhain-feed-units", args->heidenhain_feed_units,
                  "Unit of Heidenhain F words (mm/s for FreeCAD's Heidenhain post; never guessed)")
      ->check(CLI::IsMember({"mm/min", "mm/s"}));
  cmd->add_option("--level", args->level, "Conformance class of the output")->check(CLI::IsMember({"cc1", "cc2"}));
  cmd->add_option("-o,--output", args->output, "Part 21 file to write; - writes standard output")->required();
  cmd->add_option("--report", args->report, "Also write a JSON report (docs/formats/report.md)");
  cmd->add_option("--html", args->html, "Also write an HTML page: top and 3D views of the toolpaths and features (docs/viewer.md)");
  cmd->add_option("--security-plane", args->security_plane, "Security plane Z in mm (default: the highest rapid)");
  cmd->add_option("--subroutine-path", args->subroutine_path, "Directories searched for o<name> call files, ':'-separated");
  cmd->add_flag("--strict", args->strict,
                "A warning is an error: exit 1, nothing written (the interpreter refuses machine builder M codes, G43 "
                "without tool lengths at their place)");
  cmd->add_option("--machine-functions", args->machine_functions,
                  "M codes that are the machine builder's machine functions (no motion), beyond the dialect's list: "
                  "read with a warning")
      ->delimiter(',');
  cmd->add_option("--max-seconds", args->max_seconds,
                  "Stop with an error (writing nothing) once the conversion has run this long (default: no limit)")
      ->check(CLI::NonNegativeNumber);
  cmd->callback([args, cmd, &exit_code]() { exit_code = run_convert(*args, verbosity_of(*cmd)); });
}

}  // namespace ncbridge::cli
