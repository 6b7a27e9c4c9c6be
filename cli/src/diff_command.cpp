// `ncbridge diff A.stp B.stp`: compares two Part 21 files by content (instances matched by what
// they hold, not by #id) and prints the differences grouped by entity type. Exit status 0 when
// the files are semantically identical, 5 when they differ, 1 when a file cannot be read (the
// codes of every command: errors.hpp, docs/cli.md). One of the files may be "-" (standard input).
#include <CLI/CLI.hpp>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "errors.hpp"
#include "input_files.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/step_writer/express_schema.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/schema_location.hpp"
#include "ncbridge/step_writer/semantic_diff.hpp"

namespace ncbridge::cli {

namespace {

struct DiffArguments {
  std::string a, b;
  double tolerance = 1e-6;
  std::vector<std::string> ignore;
  std::vector<std::string> ignore_entities;
  bool ignore_names = false;
  std::string schema;
  bool quiet = false;
};

step_writer::part21::ReadResult read_part21(const Input& input) {
  return input.text ? step_writer::part21::read_part21(*input.text, input.name)
                    : step_writer::part21::read_part21_file(input.path);
}

int run_diff(const DiffArguments& args) {
  if (args.a == "-" && args.b == "-") throw UsageError("only one of the two files can be standard input (-)");
  if (!std::isfinite(args.tolerance) || args.tolerance < 0) {
    throw UsageError("--tolerance must be a length of 0 or more, not " + std::to_string(args.tolerance));
  }
  if (args.tolerance > 1) {
    char tolerance[32];
    std::snprintf(tolerance, sizeof tolerance, "%g", args.tolerance);
    print_warning({}, std::string("--tolerance ") + tolerance +
                          " mm is coarser than any machining tolerance: differences below it are not reported");
  }
  if (!args.schema.empty()) require_input_file(args.schema, "--schema");
  const Input input_a = open_input(args.a, "first file");
  const Input input_b = open_input(args.b, "second file");
  auto a = read_part21(input_a);
  auto b = read_part21(input_b);
  step_writer::DiffOptions options;
  options.tolerance = args.tolerance;
  options.ignore = args.ignore;
  for (std::string e : args.ignore_entities) {
    for (char& c : e) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    options.ignore_entities.push_back(e);
  }
  // Attribute names for the report and for --ignore by name: the ISO 14649 schema when found.
  std::optional<step_writer::express::Schema> schema;
  std::optional<std::filesystem::path> schema_path;
  if (!args.schema.empty()) schema_path = args.schema;
  else schema_path = step_writer::find_iso14649_schema("/proc/self/exe");
  if (schema_path) {
    try {
      schema = step_writer::express::Schema::parse_file(*schema_path);
      options.schema = &*schema;
    } catch (const InputError&) {
      if (!args.schema.empty()) throw;  // a schema the user named must read
    }
  }
  if (args.ignore_names) {
    // the paper's "only tool names differ": identifiers and names of every entity
    for (const char* attr : {"*.its_id", "*.name", "*.its_tool_id"}) options.ignore.emplace_back(attr);
    if (!options.schema) throw InputError({}, "--ignore-names needs the ISO 14649 schema (--schema FILE.exp)");
  }
  auto result = step_writer::semantic_diff(a.graph, b.graph, options);
  std::string report = step_writer::format_diff(result, input_a.name, input_b.name);
  if (!args.quiet || !result.identical()) std::fputs(report.c_str(), stdout);
  return result.identical() ? exit_status::ok : exit_status::files_differ;
}

}  // namespace

void add_diff_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<DiffArguments>();
  CLI::App* cmd = app.add_subcommand(
      "diff", "Compare two Part 21 (STEP-NC) files by content; exit 0 identical, 5 different, 1 unreadable");
  cmd->add_option("a", args->a, "First Part 21 file; - reads standard input")->required();
  cmd->add_option("b", args->b, "Second Part 21 file")->required();
  cmd->add_option("--tolerance", args->tolerance, "Absolute tolerance for real values (default 1e-6)");
  cmd->add_option("--ignore", args->ignore,
                  "Attribute left out: ENTITY.attribute (schema name or 1-based position), '*' for any entity")
      ->take_all();
  cmd->add_option("--ignore-entity", args->ignore_entities,
                  "Entity left out with all it alone leads to, e.g. TOOLPATH_LIST (compare features and operations)")
      ->take_all();
  cmd->add_flag("--ignore-names", args->ignore_names, "Leave out its_id and name attributes (tool names, ids)");
  cmd->add_option("--schema", args->schema, "EXPRESS schema for attribute names (default: ISO 14649 when found)");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing when the files are identical");
  cmd->callback([args, &exit_code]() { exit_code = run_diff(*args); });
}

}  // namespace ncbridge::cli
