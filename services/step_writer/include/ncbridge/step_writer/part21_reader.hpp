#pragma once
// Reads any ISO 10303-21 exchange structure (the :2002 and :2016 basics) into a Graph: a
// streaming tokenizer + recursive-descent parser, no regular expressions. Comments /* */ anywhere
// between tokens, multi-line instances, complex instances, the HEADER section. ANCHOR, REFERENCE
// and SIGNATURE sections are skipped with a warning; several DATA sections are merged.
//
// Syntax errors, duplicate ids and references to instances that do not exist throw
// ncbridge::InputError with the file, line and column of the offending token.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/step_writer/diagnostic.hpp"
#include "ncbridge/step_writer/part21_graph.hpp"

namespace ncbridge::step_writer::part21 {

struct ReadResult {
  Graph graph;
  std::vector<Diagnostic> warnings;  // things read but not kept, odd header content
};

// `file_name` names the input in errors and diagnostics.
ReadResult read_part21(std::string_view text, const std::string& file_name);
ReadResult read_part21_file(const std::filesystem::path& path);

}  // namespace ncbridge::step_writer::part21
