#pragma once
// Command-line mistakes in the house style (errors.hpp), with the help a user needs to fix them:
// an unknown command lists the commands and the nearest one, an unknown option the nearest
// option of its command.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
class ParseError;
}  // namespace CLI

namespace ncbridge::cli {

// The candidate nearest to `word` (edit distance, or `word` a prefix of it), if any is near.
std::optional<std::string> nearest(std::string_view word, const std::vector<std::string>& candidates);

// The message for argv's command when it is missing or not one of app's subcommands; nullopt
// when argv names a command (or asks for --help/--version).
std::optional<std::string> command_error(const CLI::App& app, int argc, const char* const* argv);

// The message for a parse error of the command argv names (one line, no "ncbridge: error:").
std::string parse_error_message(const CLI::App& app, const CLI::ParseError& e, int argc, const char* const* argv);

}  // namespace ncbridge::cli
