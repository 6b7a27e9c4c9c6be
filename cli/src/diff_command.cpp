// `ncbridge diff A.stp B.stp`: compares two Part 21 files by content (instances matched by what
// they hold, not by #id) and prints the differences grouped by entity type. Exit code 0 when
// the files are semantically identical, 1 when they differ, 2 when a file cannot be read.
#include <CLI/CLI.hpp>

#include <cctype>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
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

int run_diff(const DiffArguments& args) {
  try {
    auto a = step_writer::part21::read_part21_file(args.a);
    auto b = step_writer::part21::read_part21_file(args.b);
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
      if (!options.schema) {
        std::fprintf(stderr, "ncbridge diff: --ignore-names needs the ISO 14649 schema (--schema FILE.exp)\n");
        return 2;
      }
    }
    auto result = step_writer::semantic_diff(a.graph, b.graph, options);
    std::string report = step_writer::format_diff(result, args.a, args.b);
    if (!args.quiet || !result.identical()) std::fputs(report.c_str(), stdout);
    return result.identical() ? 0 : 1;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}

}  // namespace

void add_diff_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<DiffArguments>();
  CLI::App* cmd = app.add_subcommand(
      "diff", "Compare two Part 21 (STEP-NC) files by content; exit 0 identical, 1 different, 2 unreadable");
  cmd->add_option("a", args->a, "First Part 21 file")->required()->check(CLI::ExistingFile);
  cmd->add_option("b", args->b, "Second Part 21 file")->required()->check(CLI::ExistingFile);
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
