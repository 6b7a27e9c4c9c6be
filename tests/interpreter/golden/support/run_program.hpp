#pragma once
// Runs a program to completion, capturing its standard output and error (tests only).
#include <filesystem>
#include <string>
#include <vector>

namespace ncbridge::testing {

struct ProgramRun {
  int exit_code = -1;    // the exit status, or 128 + signal number when killed by a signal
  std::string out;       // standard output
  std::string err;       // standard error
};

struct RunOptions {
  std::filesystem::path working_directory;  // empty: the caller's
  std::vector<std::string> extra_environment;  // "NAME=value" entries added to the caller's
  bool discard_output = false;  // standard output to /dev/null (ProgramRun::out stays empty)
  std::filesystem::path standard_input;  // a file read as standard input; empty: /dev/null
};

// argv[0] is the executable path. Standard input is options.standard_input or /dev/null. Throws std::runtime_error when the
// program cannot be started.
ProgramRun run_program(const std::vector<std::string>& argv, const RunOptions& options = {});

// The full path of `name` found on PATH, or empty.
std::filesystem::path find_on_path(const std::string& name);

// True when the tests run in CI (CI=true): a reference tool that is missing there is a failure
// (scripts/install-deps.sh --tests installs every one), never a skip.
bool in_ci();

}  // namespace ncbridge::testing
