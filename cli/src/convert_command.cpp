// `ncbridge convert PROGRAM --tools T --stock S -o OUT.stp [--report R.json]`: the embedded
// pipeline interpreter -> cc1_builder -> step_writer in one process. The output is written
// atomically: a failed run leaves no file (and an old OUT.stp untouched). CC1 from a program is
// streamed: each workplan element is written (file and report) as soon as the builder finishes
// it, so memory stays flat; CC2 needs the whole CC1 model first.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <fstream>
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
#include "html_report.hpp"
#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/atomic_file.hpp"
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

nlohmann::ordered_json report_of(const ConvertArguments& args, const stepnc::Project& p,
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
  return json{{"program", args.program},
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
bool is_part21_file(const std::string& path) {
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

cc1_builder::Options builder_options(const ConvertArguments& args, const std::optional<setup::Stock>& stock) {
  cc1_builder::Options options;
  options.tools = setup::read_tool_list(args.tools);
  options.stock = *stock;
  options.security_plane_z = args.security_plane;
  return options;
}

interpreter::Options interpreter_options(const ConvertArguments& args, const setup::ToolList& tools) {
  interpreter::Options interp;
  interp.dialect = dialect_of(args.dialect);
  if (interp.dialect == interpreter::Dialect::Auto) {  // detect, and say which
    const auto detected = interpreter::detect_dialect_file(args.program);
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

void interpret(const ConvertArguments& args, const interpreter::Options& interp, TimedSink& sink) {
  try {
    interpreter::interpret_file(args.program, interp, sink);
  } catch (...) {
    sink.clear();
    throw;
  }
}

void print_warnings(const std::vector<cc1_builder::Warning>& warnings) {
  for (const auto& w : warnings) std::fprintf(stderr, "%s: warning: %s\n", w.where.to_string().c_str(), w.message.c_str());
}

// CC1 from a program, streamed: interpreter -> cc1_builder -> (Part 21 writer, report) element
// by element; the model is never whole in memory.
int run_streamed_cc1(const ConvertArguments& args, Clock::time_point t0) {
  const std::optional<setup::Stock> stock = setup::read_stock(args.stock);
  const cc1_builder::Options options = builder_options(args, stock);
  const interpreter::Options interp = interpreter_options(args, options.tools);

  step_writer::StepncWriteOptions write;
  write.file_name = std::filesystem::path(args.output).filename().string();
  step_writer::AtomicFile file(args.output);
  step_writer::StepncStreamWriter writer(write, [&](std::string_view chunk) { file.write(chunk); });
  std::optional<Cc1Report> report;
  if (!args.report.empty()) report.emplace(args.report, Cc1Report::Head{args.program, args.output, args.level});
  ElementWriter elements(writer, report ? &*report : nullptr);
  cc1_builder::Cc1Builder builder(options, &elements);
  TimedSink sink(builder, isatty(STDERR_FILENO) != 0, report.has_value());
  const auto t_interpret = Clock::now();
  interpret(args, interp, sink);
  const auto t_built = Clock::now();
  const stepnc::Project project = builder.take_project();
  const std::uint64_t bytes = writer.finish(project);
  const auto t_written = Clock::now();
  file.commit();
  const auto t_done = Clock::now();

  print_warnings(builder.warnings());
  if (report) {
    // The writer's and the report's work happens inside the builder's calls; each is counted
    // once, under step_writer.
    const double written_ms = ms(elements.spent()) + ms(t_written - t_built);
    Cc1Report::Tail tail;
    tail.canonical_calls = builder.calls_seen();
    tail.output_bytes = bytes;
    for (const auto& w : builder.warnings()) tail.warnings.emplace_back(w.where.to_string(), w.message);
    tail.timings_ms = {{"read_inputs", ms(t_interpret - t0)},
                       {"interpreter", ms(t_built - t_interpret) - ms(sink.spent())},
                       {"cc1_builder", ms(sink.spent()) - ms(elements.spent())},
                       {"step_writer", written_ms},
                       {"output", ms(t_done - t_written)},
                       {"total", ms(t_done - t0)}};
    report->commit(project, tail);
  }
  return 0;
}

int run_convert(const ConvertArguments& args) {
  const auto t0 = Clock::now();
  if (!args.html.empty() && args.level != "cc2") {
    throw InputError({args.program, 0, 0}, "--html needs --level cc2 (it draws the recognised features)");
  }
  const bool part21_input = is_part21_file(args.program);
  if (!part21_input && (args.tools.empty() || args.stock.empty())) {
    throw InputError({args.program, 0, 0}, "converting a program needs --tools and --stock");
  }
  if (!part21_input && args.level == "cc1") return run_streamed_cc1(args, t0);
  std::vector<cc1_builder::Warning> warnings;
  std::uint64_t calls = 0;
  stepnc::Project project;
  std::optional<setup::Stock> stock;
  if (!args.stock.empty()) stock = setup::read_stock(args.stock);
  Clock::time_point t_interpret, t_built;
  Clock::duration builder_spent{};
  if (part21_input) {  // the CC1 model read back: everything recognition uses is in the file
    t_interpret = Clock::now();
    auto read = step_writer::read_stepnc_file(args.program);
    for (const auto& d : read.warnings) warnings.push_back({d.where, d.message});
    project = std::move(read.project);
    if (args.level == "cc1" && needs_toolpaths(project)) {  // CC2 in: generate the toolpaths
      std::vector<std::string> notes;
      project = generate_cc1(project, stock, args.program, notes);
      for (auto& n : notes) warnings.push_back({{args.program, 0, 0}, std::move(n)});
    }
    t_built = Clock::now();
  } else {
    const cc1_builder::Options options = builder_options(args, stock);
    const interpreter::Options interp = interpreter_options(args, options.tools);
    cc1_builder::Cc1Builder builder(options);
    TimedSink sink(builder, isatty(STDERR_FILENO) != 0, !args.report.empty());
    t_interpret = Clock::now();
    interpret(args, interp, sink);
    t_built = Clock::now();
    warnings = builder.warnings();
    calls = builder.calls_seen();
    project = builder.take_project();
    builder_spent = sink.spent();
  }
  // CC2: the features recognised in the CC1 model, with their workingsteps (cc2_output.hpp).
  std::optional<Cc2Output> cc2;
  if (args.level == "cc2") cc2 = build_cc2(project, stock, args.program);
  const auto t_recognized = Clock::now();

  step_writer::StepncWriteOptions write;
  write.file_name = std::filesystem::path(args.output).filename().string();
  if (cc2) write.description = {"ISO 14649 CC2 program written by ncbridge"};
  // The text streams into the temporary file as it is made; "output" is the fsync and rename.
  step_writer::AtomicFile file(args.output);
  const std::uint64_t bytes = step_writer::write_stepnc(cc2 ? cc2->project : project, write, [&](std::string_view chunk) { file.write(chunk); });
  const auto t_written = Clock::now();
  file.commit();
  const auto t_done = Clock::now();

  if (cc2) {
    for (const auto& w : cc2->warnings) {
      cc1_builder::Warning warning;
      warning.where.file = args.program;
      warning.message = w;
      warnings.push_back(std::move(warning));
    }
  }
  print_warnings(warnings);
  if (!args.report.empty()) {
    const double builder_ms = ms(builder_spent);
    nlohmann::ordered_json timings{{"read_inputs", ms(t_interpret - t0)},
                                 {"interpreter", ms(t_built - t_interpret) - builder_ms},
                                 {"cc1_builder", builder_ms}};
    if (cc2) timings["feature_recognizer"] = ms(t_recognized - t_built);
    timings["step_writer"] = ms(t_written - t_recognized);
    timings["output"] = ms(t_done - t_written);
    timings["total"] = ms(t_done - t0);
    auto report = report_of(args, cc2 ? cc2->project : project, warnings, calls, bytes, timings);
    if (cc2) report["features"] = cc2_features_json(*cc2);
    step_writer::write_file_atomically(args.report, report.dump(2) + "\n");
  }
  if (!args.html.empty()) {
    HtmlReportInput page;
    page.title = std::filesystem::path(args.program).filename().string();
    page.cc2 = &*cc2;
    for (const auto& w : warnings) page.warnings.push_back(w.where.to_string() + ": " + w.message);
    step_writer::write_file_atomically(args.html, html_report(page));
  }
  return 0;
}

}  // namespace

void add_convert_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ConvertArguments>();
  CLI::App* cmd = app.add_subcommand("convert", "Convert a part program into an ISO 14649 (STEP-NC) Part 21 file");
  cmd->add_option("program", args->program, "Part program, a CC1 Part 21 file to raise to --level cc2, or a CC2 file to give toolpaths (--level cc1)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--tools", args->tools, "Tool list (JSON or YAML, docs/formats/tools.md); needed for a program")->check(CLI::ExistingFile);
  cmd->add_option("--stock", args->stock, "Stock block (JSON or YAML, docs/formats/stock.md); needed for a program")->check(CLI::ExistingFile);
  cmd->add_option("--dialect", args->dialect, "Program dialect")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain", "auto"}));
  cmd->add_option("--heidenhain-feed-units", args->heidenhain_feed_units,
                  "Unit of Heidenhain F words (mm/s for FreeCAD's Heidenhain post; never guessed)")
      ->check(CLI::IsMember({"mm/min", "mm/s"}));
  cmd->add_option("--level", args->level, "Conformance class of the output")->check(CLI::IsMember({"cc1", "cc2"}));
  cmd->add_option("-o,--output", args->output, "Part 21 file to write")->required();
  cmd->add_option("--report", args->report, "Also write a JSON report (docs/formats/report.md)");
  cmd->add_option("--html", args->html, "Also write an HTML page: top view, toolpaths, features (--level cc2)");
  cmd->add_option("--security-plane", args->security_plane, "Security plane Z in mm (default: the highest rapid)");
  cmd->add_option("--subroutine-path", args->subroutine_path, "Directories searched for o<name> call files, ':'-separated");
  cmd->callback([args, &exit_code]() { exit_code = run_convert(*args); });
}

}  // namespace ncbridge::cli
