// `ncbridge check FILE.stp [--schema FILE.exp]`: reads a Part 21 file and checks its instances
// against an EXPRESS schema (ISO 14649 by default). Prints each finding on standard output as
// `ncbridge: error|warning: file:line: #id ENTITY.attribute: message`, a summary on stderr, and
// exits 1 when there are errors. FILE "-" reads standard input. See docs/formats/part21.md.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <set>
#include <string>

#include "commands.hpp"
#include "errors.hpp"
#include "feedback.hpp"
#include "input_files.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/schema_check.hpp"
#include "ncbridge/step_writer/schema_location.hpp"

namespace ncbridge::cli {
namespace {

struct CheckArguments {
  std::string file;
  std::string schema;
  bool strict = false;
};

// FILE_SCHEMA names under which ISO 14649 files are published (notes/iso14649.md).
bool names_iso14649(const std::vector<std::string>& file_schema, const std::string& schema_name) {
  static const std::set<std::string> iso14649 = {"MACHINING_SCHEMA", "MILLING_SCHEMA", "TURNING_SCHEMA",
                                                 "MILLING_TOOL_SCHEMA", "TURNING_MACHINE_TOOL_SCHEMA",
                                                 "COMBINED_SCHEMA"};
  for (std::string name : file_schema) {
    if (auto brace = name.find(" {"); brace != std::string::npos) name.resize(brace);  // object identifier
    if (iso14649.count(name) || name == schema_name) return true;
  }
  return false;
}

// A finding in the house style: "ncbridge: error: file:line: #10 ENTITY.attribute: message".
std::string finding_line(const step_writer::Diagnostic& d) {
  SourceLocation at = d.where;
  at.column = 0;  // instance-level problems: the line is what a user looks for
  std::string message;
  if (d.instance != 0) {
    message = '#' + std::to_string(d.instance);
    if (!d.entity.empty()) message += ' ' + d.entity;
    if (!d.attribute.empty()) message += '.' + d.attribute;
    message += ": ";
  }
  message += d.message;
  return d.severity == step_writer::Severity::Error ? error_line(at, message) : warning_line(at, message);
}

int run_check(const CheckArguments& args, const Feedback& feedback) {
  if (!args.schema.empty()) require_input_file(args.schema, "--schema");
  std::filesystem::path schema_path = args.schema;
  if (schema_path.empty()) {
    auto found = step_writer::find_iso14649_schema("/proc/self/exe");
    if (!found) {
      throw InputError({}, "the ISO 14649 EXPRESS schema was not found; pass --schema FILE.exp or set "
                           "NCBRIDGE_ISO14649_SCHEMA");
    }
    schema_path = *found;
  }
  feedback.detail("schema: " + schema_path.string());
  const Input file = open_input(args.file, "file");
  step_writer::part21::ReadResult read = file.text ? step_writer::part21::read_part21(*file.text, file.name)
                                                   : step_writer::part21::read_part21_file(file.path);
  std::vector<step_writer::Diagnostic> diagnostics = std::move(read.warnings);

  step_writer::express::Schema schema = step_writer::express::Schema::parse_file(schema_path);

  if (args.schema.empty() && !names_iso14649(read.graph.header.schema, schema.name())) {
    step_writer::Diagnostic skipped;
    skipped.severity = step_writer::Severity::Warning;
    skipped.where.file = file.name;
    std::string names;
    for (const auto& n : read.graph.header.schema) names += (names.empty() ? "" : ", ") + n;
    skipped.message = "FILE_SCHEMA (" + names + ") is not ISO 14649: instances not checked (use --schema)";
    diagnostics.push_back(std::move(skipped));
  } else {
    step_writer::CheckOptions options{file.name, !args.strict};
    auto found = step_writer::check_instances(read.graph, schema, options);
    diagnostics.insert(diagnostics.end(), found.begin(), found.end());
  }

  for (const auto& d : diagnostics) std::printf("%s\n", finding_line(d).c_str());
  std::fflush(stdout);
  std::size_t errors = step_writer::count_errors(diagnostics);
  feedback.summary(file.name + ": " + std::to_string(read.graph.size()) + " instances, " + std::to_string(errors) +
                   " errors, " + std::to_string(diagnostics.size() - errors) + " warnings");
  return errors == 0 ? exit_status::ok : exit_status::input_error;
}

}  // namespace

void add_check_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CheckArguments>();
  CLI::App* check = app.add_subcommand("check", "Check a Part 21 file against the ISO 14649 EXPRESS schema");
  check->add_option("file", args->file, "Part 21 file (.stp); - reads standard input")->required();
  check->add_option("--schema", args->schema,
                    "EXPRESS schema (default: $NCBRIDGE_ISO14649_SCHEMA, then the installed or development copy)");
  check->add_flag("--strict", args->strict, "Report draft/published entity name variants as errors");
  check->callback([args, check, &exit_code] { exit_code = run_check(*args, Feedback(verbosity_of(*check))); });
}

}  // namespace ncbridge::cli
