// The independent check: LinuxCNC's rs274 runs every RS274/NGC program the writer makes from the
// corpus without error, and makes the same motion as ncbridge's reading of the source program.
// A missing rs274 fails the test under CI=true (scripts/install-deps.sh --tests installs it).
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include "ncbridge/common/error.hpp"
#include "ncbridge/gcode_writer/program_writer.hpp"
#include "support/corpus.hpp"
#include "support/listing.hpp"
#include "support/run_program.hpp"
#include "support/same_motion.hpp"

namespace fs = std::filesystem;
using namespace ncbridge;

namespace {

// rs274's only normal chatter on standard error.
bool rs274_reported_error(const std::string& err) {
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line != "executing") return true;
  }
  return false;
}

TEST(Rs274Check, Rs274RunsEveryWrittenProgramWithTheSourcesMotion) {
  const fs::path rs274 = ncbridge::testing::find_on_path("rs274");
  if (rs274.empty()) {
    if (ncbridge::testing::in_ci()) FAIL() << "rs274 not installed under CI=true (scripts/install-deps.sh --tests installs linuxcnc-uspace)";
    GTEST_SKIP() << "SKIPPED: rs274 not installed (Debian package linuxcnc-uspace)";
  }
  // rs274 keeps tool data in $HOME/.tool.mmap and rewrites its -v file: give it private ones.
  const fs::path scratch = fs::temp_directory_path() / ("ncbridge-gcode-rs274-" + std::to_string(::getpid()));
  fs::create_directories(scratch / "home");
  int checked = 0;
  std::vector<std::string> problems;
  for (const auto& program : ncbridge::testing::corpus_programs()) {
    const interpreter::Options reading = ncbridge::testing::reading_options(program);
    gcode_writer::Options writing;
    writing.tools = reading.tools;
    std::string written, source;
    try {
      gcode_writer::ProgramWriter writer(writing, [&](std::string_view piece) { written.append(piece); });
      source = ncbridge::testing::canon_listing(program.program, reading, &writer);
    } catch (const InputError& e) {
      problems.push_back(program.name + ": not written: " + e.what());
      continue;
    }
    const fs::path file = scratch / (ncbridge::testing::test_name(program.name) + ".ngc");
    std::ofstream(file, std::ios::binary) << written;
    const fs::path var_file = scratch / "params.var";
    std::ofstream(var_file, std::ios::trunc).close();
    ncbridge::testing::RunOptions options;
    options.working_directory = scratch;
    options.extra_environment = {"HOME=" + (scratch / "home").string()};
    const auto run = ncbridge::testing::run_program(
        {rs274.string(), "-g", "-n", "2", "-t", program.rs274_tool_table.string(), "-v", var_file.string(), file.string()},
        options);
    ++checked;
    if (run.exit_code != 0 || rs274_reported_error(run.err)) {
      problems.push_back(program.name + ": rs274 fails on the written program: " + run.err.substr(0, 400));
      continue;
    }
    const auto comparison = ncbridge::testing::compare_motion(source, run.out);
    if (!comparison.equal) problems.push_back(program.name + ": rs274's motion differs: " + comparison.report);
  }
  std::error_code ignored;
  fs::remove_all(scratch, ignored);
  EXPECT_GT(checked, 100);
  for (const auto& p : problems) ADD_FAILURE() << p;
  std::cout << "rs274 ran " << checked << " written RS274/NGC programs, " << problems.size() << " problems\n";
}

}  // namespace
