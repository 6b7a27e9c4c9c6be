// Conformance with LinuxCNC: every sample program LinuxCNC ships (under /usr/share/linuxcnc/ncfiles
// and /usr/share/doc/linuxcnc/examples) that its standalone `rs274` runs without error is run
// through both rs274 and `ncbridge canon`, and the calls are compared as in the golden tests.
// Skipped when rs274 is not installed. Programs outside ncbridge's scope are listed, with the
// reason, in conformance_exclusions.txt. Set NCBRIDGE_CONFORMANCE_DIRS (colon-separated) to
// search other folders.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "support/canon_listing.hpp"
#include "support/run_program.hpp"

namespace fs = std::filesystem;
using ncbridge::testing::run_program;

namespace {

const fs::path kTestDir = fs::path(NCBRIDGE_SOURCE_DIR) / "tests/interpreter";
constexpr const char* kTimeoutSeconds = "120";

struct Exclusion {
  std::string fragment;
  std::string reason;
};

std::vector<Exclusion> read_exclusions() {
  std::vector<Exclusion> out;
  std::ifstream in(kTestDir / "conformance_exclusions.txt");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    Exclusion e;
    if (!(words >> e.fragment) || e.fragment[0] == '#') continue;
    std::getline(words >> std::ws, e.reason);
    out.push_back(e);
  }
  return out;
}

std::vector<fs::path> sample_programs() {
  std::vector<std::string> roots = {"/usr/share/linuxcnc/ncfiles", "/usr/share/doc/linuxcnc/examples"};
  if (const char* dirs = std::getenv("NCBRIDGE_CONFORMANCE_DIRS")) {
    roots.clear();
    std::istringstream list(dirs);
    for (std::string d; std::getline(list, d, ':');) roots.push_back(d);
  }
  std::set<fs::path> unique;
  for (const auto& root : roots) {
    std::error_code ec;
    for (fs::recursive_directory_iterator it(root, fs::directory_options::follow_directory_symlink, ec), end;
         !ec && it != end; it.increment(ec)) {
      const auto ext = it->path().extension();
      if (it->is_regular_file() && (ext == ".ngc" || ext == ".nc")) unique.insert(fs::canonical(it->path()));
    }
  }
  return {unique.begin(), unique.end()};
}

// rs274's only normal chatter on standard error.
bool rs274_reported_error(const std::string& err) {
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line != "executing") return true;
  }
  return false;
}

}  // namespace

TEST(Rs274Conformance, SampleProgramsAgreeWithRs274) {
  const fs::path rs274 = ncbridge::testing::find_on_path("rs274");
  if (rs274.empty()) {
    if (ncbridge::testing::in_ci()) FAIL() << "rs274 not installed under CI=true (scripts/install-deps.sh --tests installs linuxcnc-uspace)";
    GTEST_SKIP() << "SKIPPED: rs274 not installed (Debian package linuxcnc-uspace)";
  }
  const fs::path timeout = ncbridge::testing::find_on_path("timeout");
  ASSERT_FALSE(timeout.empty()) << "coreutils `timeout` not found";

  const auto programs = sample_programs();
  if (programs.empty()) GTEST_SKIP() << "SKIPPED: no LinuxCNC sample programs found";
  const auto exclusions = read_exclusions();
  const fs::path tools = kTestDir / "conformance_tools.tbl";

  // rs274 keeps tool data in $HOME/.tool.mmap and rewrites its -v file: give it private ones.
  const fs::path scratch = fs::temp_directory_path() / ("ncbridge-conformance-" + std::to_string(::getpid()));
  fs::create_directories(scratch / "home");
  const fs::path var_file = scratch / "params.var";

  int agree = 0, excluded = 0, not_standalone = 0;
  std::vector<std::string> disagreements;
  for (const auto& program : programs) {
    const std::string path = program.string();
    const auto exclusion = std::find_if(exclusions.begin(), exclusions.end(),
                                        [&](const Exclusion& e) { return path.find(e.fragment) != std::string::npos; });
    if (exclusion != exclusions.end()) {
      ++excluded;
      continue;
    }
    std::ofstream(var_file, std::ios::trunc).close();
    ncbridge::testing::RunOptions in_program_dir;
    in_program_dir.working_directory = program.parent_path();  // where rs274 looks for o<name> files
    in_program_dir.extra_environment = {"HOME=" + (scratch / "home").string()};
    const auto reference = run_program({timeout.string(), kTimeoutSeconds, rs274.string(), "-g", "-n", "2",
                                        "-t", tools.string(), "-v", var_file.string(), path},
                                       in_program_dir);
    if (reference.exit_code != 0 || rs274_reported_error(reference.err)) {
      ++not_standalone;
      continue;
    }
    const auto ours = run_program({timeout.string(), kTimeoutSeconds, NCBRIDGE_EXECUTABLE, "canon", path,
                                   "--tool-table", tools.string(), "--tool-table-units", "inch",
                                   "--subroutine-path", program.parent_path().string()});
    std::string why;
    if (ours.exit_code != 0) {
      why = "ncbridge failed (exit " + std::to_string(ours.exit_code) + "): " + ours.err.substr(0, ours.err.find('\n'));
    } else {
      const auto comparison = ncbridge::testing::compare_canon_listings(
          ncbridge::testing::parse_canon_listing(reference.out), ncbridge::testing::parse_canon_listing(ours.out));
      if (!comparison.equal) why = comparison.report;
    }
    if (why.empty()) {
      ++agree;
    } else {
      disagreements.push_back(path + ": " + why);
    }
  }
  std::error_code ignored;
  fs::remove_all(scratch, ignored);

  std::ostringstream summary;
  summary << "rs274 conformance: " << agree << " agree, " << disagreements.size() << " disagree, "
          << not_standalone << " not runnable standalone by rs274, " << excluded
          << " excluded (conformance_exclusions.txt), of " << programs.size() << " sample programs\n";
  for (const auto& d : disagreements) summary << "DISAGREE " << d << "\n";
  std::cout << summary.str();
  EXPECT_GT(agree + static_cast<int>(disagreements.size()), 0) << "no sample program ran under rs274";
  EXPECT_TRUE(disagreements.empty()) << disagreements.size() << " sample programs disagree (listed above)";
}
