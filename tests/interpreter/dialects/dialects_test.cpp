// Dialect front-ends, through `ncbridge canon --dialect X` as a user runs them:
//  - hand-written parts (parts/NAME/) in Fanuc, Mach3/4, SINUMERIK 840D, Heidenhain and
//    RS274/NGC move the tool exactly as LinuxCNC's rs274 does on the RS274/NGC version
//    (expected/NAME.rs274.canon, made by regenerate.sh), within 0.01 mm;
//  - the paper's cross-dialect identity on the CAM corpus: every post of a part (Fanuc,
//    Mach3/4, Heidenhain) moves the tool as the LinuxCNC post does;
//  - and the same through the whole pipeline, as the paper validated its meta-model: the CC2
//    files converted from each post have the same features, operations and strategies as the
//    LinuxCNC post's, by `ncbridge diff` (instances matched by content, 0.01 mm);
//  - CAM_TEST.MPF (the corpus' real SINUMERIK program) interprets;
//  - the Heidenhain feed unit is what the user says, never guessed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "motion_path.hpp"
#include "support/run_program.hpp"

namespace fs = std::filesystem;
using ncbridge::testing::compare_tool_paths;
using ncbridge::testing::run_program;
using ncbridge::testing::tool_path;

namespace {

const fs::path kHere = fs::path(NCBRIDGE_SOURCE_DIR) / "tests/interpreter/dialects";
const fs::path kCam = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/cam";
constexpr double kTolerance = 0.01;  // mm, the paper's placement tolerance

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

ncbridge::testing::ProgramRun canon(const fs::path& program, const std::string& dialect, const fs::path& tools,
                                    std::vector<std::string> extra = {}) {
  std::vector<std::string> argv = {NCBRIDGE_EXECUTABLE, "canon", program.string(), "--dialect", dialect};
  if (!tools.empty()) {
    argv.push_back("--tools");
    argv.push_back(tools.string());
  }
  argv.insert(argv.end(), extra.begin(), extra.end());
  return run_program(argv, {program.parent_path(), {}});
}

struct PartCase {
  std::string part;
  std::string dialect;
  std::string file;
};

std::string case_name(const ::testing::TestParamInfo<PartCase>& info) {
  return info.param.part + "_" + info.param.dialect;
}

class HandWrittenPart : public ::testing::TestWithParam<PartCase> {};

TEST_P(HandWrittenPart, MovesAsLinuxCncOnTheRs274Version) {
  const PartCase& c = GetParam();
  const fs::path expected_file = kHere / "expected" / (c.part + ".rs274.canon");
  ASSERT_TRUE(fs::exists(expected_file)) << "run regenerate.sh";
  const auto expected = tool_path(read_file(expected_file));
  ASSERT_GT(expected.size(), 10u);
  const auto run = canon(kHere / "parts" / c.part / c.file, c.dialect, kHere / "parts/tools.json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto comparison = compare_tool_paths(expected, tool_path(run.out), kTolerance);
  EXPECT_TRUE(comparison.equal) << c.part << " (" << c.dialect << "): " << comparison.report;
}

std::vector<PartCase> part_cases() {
  std::vector<PartCase> cases;
  for (const char* part : {"plate", "bolt_circle", "macro_pocket"}) {
    cases.push_back({part, "rs274ngc", "part.ngc"});
    cases.push_back({part, "fanuc", "part.fanuc.nc"});
    cases.push_back({part, "mach3", "part.mach3.tap"});
    cases.push_back({part, "siemens840d", "part.mpf"});
    cases.push_back({part, "heidenhain", "part.h"});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Parts, HandWrittenPart, ::testing::ValuesIn(part_cases()), case_name);

// ---- single constructs per dialect: <dialect>/NAME.<ext> against its hand-written NAME.ngc

struct ConstructCase {
  std::string dialect;
  fs::path program;
};

std::vector<ConstructCase> construct_cases() {
  std::vector<ConstructCase> cases;
  for (const char* dialect : {"fanuc", "mach3", "siemens840d", "heidenhain"}) {
    if (!fs::exists(kHere / dialect)) continue;
    for (const auto& entry : fs::directory_iterator(kHere / dialect)) {
      // programs the constructs call (Heidenhain CALL PGM) sit in subdirectories
      // and SINUMERIK subprograms (.SPF) beside the program that calls them
      std::string ext = entry.path().extension().string();
      for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if (entry.is_regular_file() && ext != ".ngc" && ext != ".spf") cases.push_back({dialect, entry.path()});
    }
  }
  std::sort(cases.begin(), cases.end(), [](const auto& a, const auto& b) { return a.program < b.program; });
  return cases;
}

class DialectConstruct : public ::testing::TestWithParam<ConstructCase> {};

TEST_P(DialectConstruct, MovesAsLinuxCncOnItsRs274Equivalent) {
  const ConstructCase& c = GetParam();
  const std::string name = c.program.stem().string();
  ASSERT_TRUE(fs::exists(c.program.parent_path() / (name + ".ngc"))) << "no RS274/NGC equivalent for " << c.program;
  const fs::path expected_file = kHere / "expected" / c.dialect / (name + ".rs274.canon");
  ASSERT_TRUE(fs::exists(expected_file)) << "run regenerate.sh";
  const auto expected = tool_path(read_file(expected_file));
  ASSERT_GT(expected.size(), 5u);
  const auto run = canon(c.program, c.dialect, kHere / "parts/tools.json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto comparison = compare_tool_paths(expected, tool_path(run.out), kTolerance);
  EXPECT_TRUE(comparison.equal) << c.program << ": " << comparison.report;
}

TEST(DialectConstructs, EveryDialectHasSome) {
  std::set<std::string> dialects;
  for (const auto& c : construct_cases()) dialects.insert(c.dialect);
  EXPECT_EQ(dialects.size(), 4u);
}

INSTANTIATE_TEST_SUITE_P(Constructs, DialectConstruct, ::testing::ValuesIn(construct_cases()),
                         [](const ::testing::TestParamInfo<ConstructCase>& case_info) {
                           return case_info.param.dialect + "_" + case_info.param.program.stem().string();
                         });

// ---- the CAM corpus: every post of a part against its LinuxCNC post

struct PostCase {
  std::string part;
  std::string dialect;
  std::string file;
};

class CamCorpusPost : public ::testing::TestWithParam<PostCase> {};

fs::path linuxcnc_post(const fs::path& dir) {
  return fs::exists(dir / "part.linuxcnc.ngc") ? dir / "part.linuxcnc.ngc" : dir / "part.nc";
}

TEST_P(CamCorpusPost, MovesAsTheLinuxCncPost) {
  const PostCase& c = GetParam();
  const fs::path dir = kCam / c.part;
  if (!fs::exists(dir / c.file)) GTEST_SKIP() << "no " << c.file << " for " << c.part;
  const auto reference = canon(linuxcnc_post(dir), "rs274ngc", dir / "tools.json");
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  std::vector<std::string> extra;
  // FreeCAD's Heidenhain post writes F in mm/s (shared/corpus/README.md): said, not guessed
  if (c.dialect == "heidenhain") extra = {"--heidenhain-feed-units", "mm/s"};
  const auto run = canon(dir / c.file, c.dialect, dir / "tools.json", extra);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto expected = tool_path(reference.out);
  ASSERT_GT(expected.size(), 50u);
  const auto comparison = compare_tool_paths(expected, tool_path(run.out), kTolerance);
  EXPECT_TRUE(comparison.equal) << c.part << " " << c.file << ": " << comparison.report;
}

std::vector<PostCase> post_cases() {
  std::vector<PostCase> cases;
  for (const char* part : {"p01_block_reference", "p02_plate_center_zero", "p03_bracket_steps", "p04_open_pockets",
                           "p05_slots"}) {
    bool fanuc_is_part_nc = fs::exists(kCam / part / "part.linuxcnc.ngc");
    cases.push_back({part, "fanuc", fanuc_is_part_nc ? "part.nc" : "part.fanuc.nc"});
    cases.push_back({part, "mach3", "part.mach3_mach4.tap"});
    cases.push_back({part, "heidenhain", "part.heidenhain.h"});
    cases.push_back({part, "auto", "part.heidenhain.h"});
  }
  return cases;
}

std::string post_name(const ::testing::TestParamInfo<PostCase>& info) {
  return info.param.part + "_" + info.param.dialect;
}

INSTANTIATE_TEST_SUITE_P(Cam, CamCorpusPost, ::testing::ValuesIn(post_cases()), post_name);

// The paper's validation: one part, posted for several controllers, gives the same STEP-NC.
class CamCorpusStepNc : public ::testing::TestWithParam<std::string> {};

fs::path convert(const fs::path& program, const std::string& dialect, const std::string& level, const fs::path& out) {
  const fs::path dir = program.parent_path();
  std::vector<std::string> argv = {NCBRIDGE_EXECUTABLE, "convert", program.string(), "--dialect", dialect,
                                   "--level", level, "--tools", (dir / "tools.json").string(),
                                   "--stock", (dir / "stock.json").string(), "-o", out.string()};
  if (dialect == "heidenhain") {
    argv.push_back("--heidenhain-feed-units");
    argv.push_back("mm/s");
  }
  const auto run = run_program(argv);
  EXPECT_EQ(run.exit_code, 0) << program << ": " << run.err;
  return out;
}

// Differences a post really has, beyond representation: FreeCAD's Heidenhain post writes the
// old pecking cycle without the dwell of the G82 hole (CYCL DEF 1.4 DWELL 0 where the LinuxCNC
// post has P0.5), so its drilling operation has no dwell at the bottom.
struct KnownDifference {
  std::string part, dialect, row;
};
const std::vector<KnownDifference> kKnownDifferences = {
    {"p02_plate_center_zero", "heidenhain", "dwell_time_bottom  0.5"},
};

TEST_P(CamCorpusStepNc, EveryPostHasTheFeaturesOperationsAndStrategiesOfTheLinuxCncPost) {
  const std::string part = GetParam();
  const fs::path dir = kCam / part;
  const fs::path work = fs::temp_directory_path() / ("ncbridge_dialects_" + part + "_" + std::to_string(::getpid()));
  fs::create_directories(work);
  const fs::path reference = convert(linuxcnc_post(dir), "rs274ngc", "cc2", work / "linuxcnc.cc2.stp");
  for (const PostCase& c : post_cases()) {
    if (c.part != part || c.dialect == "auto") continue;
    const fs::path other = convert(dir / c.file, c.dialect, "cc2", work / (c.dialect + ".cc2.stp"));
    // Features, operations, strategies, technology and tools; the explicit toolpaths are
    // compared move by move above (posts differ in how they split them: FreeCAD's Fanuc and
    // Heidenhain posts leave out blocks that do not move, the LinuxCNC post keeps them).
    // 0.01 mm: Heidenhain F words are whole mm/s, and the posts round coordinates differently.
    const auto diff = run_program({NCBRIDGE_EXECUTABLE, "diff", reference.string(), other.string(), "--tolerance",
                                   "0.01", "--ignore-entity", "TOOLPATH_LIST"});
    std::vector<std::string> expected_rows;
    for (const auto& k : kKnownDifferences) {
      if (k.part == part && k.dialect == c.dialect) expected_rows.push_back(k.row);
    }
    if (expected_rows.empty()) {
      EXPECT_EQ(diff.exit_code, 0) << part << " " << c.file << ":\n" << diff.out << diff.err;
      EXPECT_NE(diff.out.find("identical"), std::string::npos) << diff.out;
    } else {
      EXPECT_EQ(diff.exit_code, 5) << diff.out << diff.err;  // 5: the files differ (docs/cli.md)
      for (const auto& row : expected_rows) EXPECT_NE(diff.out.find(row), std::string::npos) << diff.out;
      EXPECT_NE(diff.out.find(std::to_string(expected_rows.size()) + " attribute differences; 0 only in A; 0 only in B"),
                std::string::npos)
          << diff.out;
    }
  }
  fs::remove_all(work);
}

INSTANTIATE_TEST_SUITE_P(Cam, CamCorpusStepNc,
                         ::testing::Values("p01_block_reference", "p02_plate_center_zero", "p03_bracket_steps",
                                           "p04_open_pockets", "p05_slots"));

TEST(CamCorpus, EveryPartHasTheFourPosts) {
  int parts = 0;
  for (const auto& entry : fs::directory_iterator(kCam)) {
    if (!entry.is_directory()) continue;
    ++parts;
    EXPECT_TRUE(fs::exists(entry.path() / "part.heidenhain.h")) << entry.path();
    EXPECT_TRUE(fs::exists(entry.path() / "part.mach3_mach4.tap")) << entry.path();
  }
  EXPECT_EQ(parts, 5);
}

// ---- SINUMERIK: the corpus' one real program

TEST(Sinumerik, CamTestMpfInterprets) {
  const fs::path program = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/dialects/sinumerik/CAM_TEST.MPF";
  const auto run = canon(program, "siemens840d", {});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto path = tool_path(run.out);
  EXPECT_GT(path.size(), 900u);
  // T="DRILL 8.5" has no tool list entry: numbered, and said so
  EXPECT_NE(run.out.find("tool \"DRILL 8.5\" has no tool list entry: numbered T1"), std::string::npos);
  EXPECT_NE(run.out.find("MESSAGE(\"NONE\")"), std::string::npos);
  // N200: G3 helix from (165.356, 114.944, 53) to (165.434, 122.046, 49) about I1.46 J3.535
  bool helix = false;
  for (const auto& m : path) {
    if (m.name == "ARC_FEED" && std::fabs(m.values[0] - 165.434) < 1e-3 && std::fabs(m.values[2] - 166.816) < 1e-3 &&
        std::fabs(m.values[5] - 49.0) < 1e-3 && m.values[4] == 1) {
      helix = true;
    }
  }
  EXPECT_TRUE(helix);
  EXPECT_NE(run.out.find("PROGRAM_END()"), std::string::npos);
}

TEST(Sinumerik, AutoDetectsCamTest) {
  const fs::path program = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/dialects/sinumerik/CAM_TEST.MPF";
  const auto run = canon(program, "auto", {});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("dialect siemens840d (detected:"), std::string::npos) << run.err;
}

// SINUMERIK POCKET3/POCKET4 through the whole pipeline: the recogniser, which knows nothing of
// the cycles, finds the pockets as programmed in the moves the decomposition made.
TEST(Sinumerik, PocketCyclesAreRecognisedAsTheirPockets) {
  const fs::path dir = kHere / "recognised";
  const fs::path work = fs::temp_directory_path() / ("ncbridge_pockets_" + std::to_string(::getpid()));
  fs::create_directories(work);
  const auto run = run_program({NCBRIDGE_EXECUTABLE, "convert", (dir / "sinumerik_pockets.mpf").string(), "--dialect",
                                "siemens840d", "--tools", (kHere / "parts/tools.json").string(), "--stock",
                                (dir / "stock.json").string(), "--level", "cc2", "-o", (work / "p.stp").string(),
                                "--report", (work / "p.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(read_file(work / "p.json"));
  fs::remove_all(work);
  const auto& features = report.at("features");
  ASSERT_EQ(features.size(), 2u) << features.dump(1);
  const auto& round = features[0];
  EXPECT_EQ(round.at("type"), "closed_pocket");
  EXPECT_NEAR(round.at("center_xy")[0].get<double>(), 25.0, kTolerance);
  EXPECT_NEAR(round.at("center_xy")[1].get<double>(), 40.0, kTolerance);
  EXPECT_NEAR(round.at("depth").get<double>(), 6.0, kTolerance);
  EXPECT_NEAR(round.at("dimensions").at("diameter").get<double>(), 30.0, 0.05);  // the rings' chords
  EXPECT_EQ(round.at("operations")[0].at("strategy"), "contour_parallel");
  EXPECT_EQ(round.at("operations")[0].at("layers"), 2);
  const auto& box = features[1];
  EXPECT_EQ(box.at("type"), "closed_pocket");
  EXPECT_NEAR(box.at("center_xy")[0].get<double>(), 70.0, kTolerance);
  EXPECT_NEAR(box.at("center_xy")[1].get<double>(), 40.0, kTolerance);
  EXPECT_NEAR(box.at("depth").get<double>(), 4.0, kTolerance);
  EXPECT_NEAR(box.at("dimensions").at("length").get<double>(), 30.0, kTolerance);
  EXPECT_NEAR(box.at("dimensions").at("width").get<double>(), 20.0, kTolerance);
  EXPECT_NEAR(box.at("dimensions").at("corner_radius").get<double>(), 6.0, 0.05);
}

// ---- Heidenhain feed units: what the user says, never guessed

TEST(Heidenhain, FeedUnitIsMillimetresPerMinuteUnlessToldOtherwise) {
  const fs::path dir = kCam / "p01_block_reference";
  const auto per_minute = canon(dir / "part.heidenhain.h", "heidenhain", dir / "tools.json");
  const auto per_second = canon(dir / "part.heidenhain.h", "heidenhain", dir / "tools.json",
                                {"--heidenhain-feed-units", "mm/s"});
  ASSERT_EQ(per_minute.exit_code, 0) << per_minute.err;
  ASSERT_EQ(per_second.exit_code, 0) << per_second.err;
  // block 5: L Z30.000 R0 F5 M
  EXPECT_NE(per_minute.out.find("SET_FEED_RATE(5.0000)"), std::string::npos);
  EXPECT_EQ(per_minute.out.find("SET_FEED_RATE(300.0000)"), std::string::npos);
  EXPECT_NE(per_second.out.find("SET_FEED_RATE(300.0000)"), std::string::npos);
}

}  // namespace

namespace {

// ---- --dialect auto without the posts' comments (issue 16): every post of the CAM corpus with
// its comments removed is read in its dialect. FreeCAD's Mach3/4 and LinuxCNC posts are the same
// text once their comments are gone: auto names Mach3 among the readings that read it whole with
// the same tool path (the one it takes, RS274/NGC, moves the tool exactly as the Mach3 reading).

std::string strip_comments(const std::string& text) {
  std::string out;
  int depth = 0;
  bool line_comment = false;
  for (char c : text) {
    if (c == '\n') {
      line_comment = false;
      depth = 0;
      out.push_back(c);
      continue;
    }
    if (line_comment) continue;
    if (c == '(') { ++depth; continue; }
    if (c == ')' && depth > 0) { --depth; continue; }
    if (depth > 0) continue;
    if (c == ';') { line_comment = true; continue; }
    out.push_back(c);
  }
  return out;
}

std::string detected_line(const std::string& err) {
  const std::size_t at = err.find("ncbridge: dialect ");
  return at == std::string::npos ? std::string() : err.substr(at, err.find('\n', at) - at);
}

TEST(DialectDetection, CommentFreeCamPostsAreReadInTheirDialect) {
  const fs::path work = fs::temp_directory_path() / ("ncbridge_detect_" + std::to_string(::getpid()));
  fs::create_directories(work);
  int checked = 0;
  for (const char* part : {"p01_block_reference", "p02_plate_center_zero", "p03_bracket_steps", "p04_open_pockets",
                           "p05_slots"}) {
    const fs::path dir = kCam / part;
    const bool fanuc_is_part_nc = fs::exists(dir / "part.linuxcnc.ngc");
    const std::vector<std::pair<std::string, std::string>> posts = {
        {fanuc_is_part_nc ? "part.nc" : "part.fanuc.nc", "fanuc"},
        {fanuc_is_part_nc ? "part.linuxcnc.ngc" : "part.nc", "rs274ngc"},
        {"part.heidenhain.h", "heidenhain"},
        {"part.mach3_mach4.tap", "mach3"}};
    for (const auto& [file, dialect] : posts) {
      const fs::path stripped = work / (std::string(part) + "_" + file);
      std::ofstream(stripped, std::ios::binary) << strip_comments(read_file(dir / file));
      std::vector<std::string> extra;
      if (dialect == "heidenhain") extra = {"--heidenhain-feed-units", "mm/s"};
      const auto run = canon(stripped, "auto", dir / "tools.json", extra);
      ASSERT_EQ(run.exit_code, 0) << stripped << ": " << run.err;
      const std::string line = detected_line(run.err);
      if (dialect != "mach3") {
        EXPECT_EQ(line.rfind("ncbridge: dialect " + dialect + " ", 0), 0u) << stripped << ": " << line;
      } else {
        const std::size_t whole = line.find("read whole as ");
        ASSERT_NE(whole, std::string::npos) << line;
        const std::string readers = line.substr(whole, line.find(" with the same tool path") - whole);
        EXPECT_NE(readers.find("mach3"), std::string::npos) << line;
        EXPECT_NE(line.find("with the same tool path"), std::string::npos) << line;
        const auto as_mach3 = canon(stripped, "mach3", dir / "tools.json");
        ASSERT_EQ(as_mach3.exit_code, 0) << as_mach3.err;
        const auto comparison = compare_tool_paths(tool_path(as_mach3.out), tool_path(run.out), 1e-9);
        EXPECT_TRUE(comparison.equal) << stripped << ": " << comparison.report;
      }
      ++checked;
    }
  }
  fs::remove_all(work);
  EXPECT_EQ(checked, 20);
}

// Programs in the style of the common Mach3 posts (our own text): recognised by what they contain.
TEST(DialectDetection, MachThreePostsAreRecognised) {
  const fs::path dir = kHere / "detection";
  for (const char* file : {"pcbgcode_mach3.tap", "cambam_mach3.nc", "vectric_mach3.txt", "estlcam_mach3.nc"}) {
    const auto run = canon(dir / file, "auto", {});
    EXPECT_EQ(run.exit_code, 0) << file << ": " << run.err;
    EXPECT_EQ(detected_line(run.err).rfind("ncbridge: dialect mach3 (detected: ", 0), 0u) << file << ": " << run.err;
  }
  // Fusion's Mach3 post names no controller: every reading that reads it moves the tool alike
  const auto fusion = canon(dir / "fusion_mach3.tap", "auto", {});
  EXPECT_EQ(fusion.exit_code, 0) << fusion.err;
  const std::string line = detected_line(fusion.err);
  EXPECT_NE(line.find("mach3"), std::string::npos) << line;
  EXPECT_NE(line.find("with the same tool path"), std::string::npos) << line;
}

}  // namespace
