// `ncbridge check FILE.stp [--schema FILE.exp]`: reads a Part 21 file and checks its instances
// against an EXPRESS schema (ISO 14649 by default). Prints `file:line: error|warning: ...`,
// exits 1 when there are errors. See docs/formats/part21.md.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <set>
#include <string>

#include "commands.hpp"
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

int run_check(const CheckArguments& args) {
  step_writer::part21::ReadResult read = step_writer::part21::read_part21_file(args.file);
  std::vector<step_writer::Diagnostic> diagnostics = std::move(read.warnings);

  std::filesystem::path schema_path = args.schema;
  if (schema_path.empty()) {
    auto found = step_writer::find_iso14649_schema("/proc/self/exe");
    if (!found) {
      std::fprintf(stderr,
                   "ncbridge check: error: the ISO 14649 EXPRESS schema was not found; pass --schema FILE.exp "
                   "or set NCBRIDGE_ISO14649_SCHEMA\n");
      return 2;
    }
    schema_path = *found;
  }
  step_writer::express::Schema schema = step_writer::express::Schema::parse_file(schema_path);

  if (args.schema.empty() && !names_iso14649(read.graph.header.schema, schema.name())) {
    step_writer::Diagnostic skipped;
    skipped.severity = step_writer::Severity::Warning;
    skipped.where.file = args.file;
    std::string names;
    for (const auto& n : read.graph.header.schema) names += (names.empty() ? "" : ", ") + n;
    skipped.message = "FILE_SCHEMA (" + names + ") is not ISO 14649: instances not checked (use --schema)";
    diagnostics.push_back(std::move(skipped));
  } else {
    step_writer::CheckOptions options{args.file, !args.strict};
    auto found = step_writer::check_instances(read.graph, schema, options);
    diagnostics.insert(diagnostics.end(), found.begin(), found.end());
  }

  for (const auto& d : diagnostics) std::printf("%s\n", d.to_string().c_str());
  std::size_t errors = step_writer::count_errors(diagnostics);
  std::fprintf(stderr, "%s: %zu instances, %zu errors, %zu warnings\n", args.file.c_str(), read.graph.size(), errors,
               diagnostics.size() - errors);
  return errors == 0 ? 0 : 1;
}

}  // namespace

void add_check_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CheckArguments>();
  CLI::App* check = app.add_subcommand("check", "Check a Part 21 file against the ISO 14649 EXPRESS schema");
  check->add_option("file", args->file, "Part 21 file (.stp)")->required()->check(CLI::ExistingFile);
  check->add_option("--schema", args->schema,
                    "EXPRESS schema (default: $NCBRIDGE_ISO14649_SCHEMA, then the installed or development copy)")
      ->check(CLI::ExistingFile);
  check->add_flag("--strict", args->strict, "Report draft/published entity name variants as errors");
  check->callback([args, &exit_code] { exit_code = run_check(*args); });
}

}  // namespace ncbridge::cli
