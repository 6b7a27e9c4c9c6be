#pragma once
// How every `ncbridge` subcommand says what went wrong (docs/cli.md): one line on stderr,
//   ncbridge: error: FILE:LINE:COLUMN: message       (the location where there is one)
//   ncbridge: warning: FILE:LINE: message
// and an exit status that says which kind of failure it was, the same in every subcommand.
// Commands throw; main() prints and picks the status (report_exception).
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "ncbridge/common/error.hpp"

namespace ncbridge::cli {

namespace exit_status {
inline constexpr int ok = 0;
inline constexpr int input_error = 1;          // an input is missing, unreadable or wrong; check: errors found; --strict: warnings
inline constexpr int usage_error = 2;          // the command line: unknown command or option, bad or conflicting values
inline constexpr int output_error = 3;         // an output cannot be written (found before work starts, or on the way)
inline constexpr int service_unavailable = 4;  // no ncbridge service answered, or a job did not end within --timeout
inline constexpr int files_differ = 5;         // diff: the two files differ
inline constexpr int internal_error = 70;      // a bug in ncbridge (sysexits' EX_SOFTWARE)
}  // namespace exit_status

// The command line asks for something that cannot be done as asked (found after parsing).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An output path that cannot be written; `path` as the user named it.
class OutputError : public std::runtime_error {
 public:
  OutputError(std::filesystem::path path, const std::string& message);
  const std::filesystem::path& path() const noexcept { return path_; }
  const std::string& message() const noexcept { return message_; }

 private:
  std::filesystem::path path_;
  std::string message_;
};

// No service answered on the bus, or a job did not end in time.
class ServiceUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "ncbridge: error: where: message" (no location when `where` names no file).
std::string error_line(const SourceLocation& where, std::string_view message);
std::string warning_line(const SourceLocation& where, std::string_view message);

void print_error(const SourceLocation& where, std::string_view message);
void print_error(std::string_view message);
void print_error(const InputError& e);
void print_warning(const SourceLocation& where, std::string_view message);

// Prints the exception in flight (InputError, OutputError, UsageError, ServiceUnavailable, or
// anything else as an internal error) and returns its exit status.
int report_exception(std::exception_ptr e);

}  // namespace ncbridge::cli
