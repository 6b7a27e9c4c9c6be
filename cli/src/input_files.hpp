#pragma once
// Inputs named on the command line, checked before any work starts. "-" is standard input,
// read whole when opened (messages call it "<stdin>"); anything else must be a readable file.
//
//   const Input program = open_input(args.program, "program");   // InputError when missing
//   if (program.text) interpret_text(*program.text, program.name, ...);
//   else interpret_file(program.path, ...);
//   require_input_file(args.tools, "--tools");                    // a file only, no "-"
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace ncbridge::cli {

struct Input {
  std::string name;                // the path as given, or "<stdin>"
  std::filesystem::path path;      // empty for standard input
  std::optional<std::string> text; // standard input's contents
  bool from_stdin() const { return text.has_value(); }
};

// Throws InputError (file: no such file / is a directory / cannot read) naming `what`.
Input open_input(const std::string& argument, std::string_view what);
void require_input_file(const std::string& path, std::string_view what);

// The first `bytes` of an input (its head, e.g. to recognise a format).
std::string input_head(const Input& input, std::size_t bytes);

}  // namespace ncbridge::cli
