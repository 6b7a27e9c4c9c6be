// The --html page's content without a browser (tests/cli/html_viewer_test.sh runs it in one):
// a program's CC1 model, the CC1 model generated from a CC2 file (the CC2 features outlined, the
// generated toolpaths drawn and tied to them by workingstep), and a plan with its toolpaths.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_files.hpp"
#include "support/run_program.hpp"

namespace ncbridge::cli {
namespace {

namespace fs = std::filesystem;
using ncbridge::testing::ProgramRun;

const fs::path kPlate = fs::path(NCBRIDGE_SOURCE_DIR) / "examples" / "plate";
const fs::path kPart = fs::path(NCBRIDGE_SOURCE_DIR) / "examples" / "part";

fs::path fresh_directory(const std::string& name) { return ncbridge::testing::fresh_test_directory("cli_html", name); }

using ncbridge::testing::slurp;

ProgramRun ncbridge(std::vector<std::string> args) {
  args.insert(args.begin(), NCBRIDGE_EXECUTABLE);
  return ncbridge::testing::run_program(args, {{}, {"SOURCE_DATE_EPOCH=1700000000"}, false});
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// The page's "wsf" array: the feature of each workingstep (-1: none).
std::vector<int> workingstep_features(const std::string& page) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(page, m, std::regex("\"wsf\":\\[([-0-9,]*)\\]")));
  std::vector<int> out;
  std::stringstream in(m[1].str());
  for (std::string item; std::getline(in, item, ',');) out.push_back(std::stoi(item));
  return out;
}

std::vector<std::string> plate_args(const fs::path& dir, const std::string& level, const std::string& name) {
  return {"convert", (kPlate / "plate.ngc").string(), "--tools", (kPlate / "tools.json").string(), "--stock",
          (kPlate / "stock.json").string(), "--level", level, "-o", (dir / (name + ".stp")).string(), "--html",
          (dir / (name + ".html")).string()};
}

TEST(HtmlPage, AProgramsCc1ModelIsDrawnWithItsToolpathFeaturesAndHoles) {
  const fs::path dir = fresh_directory("cc1");
  const ProgramRun r = ncbridge(plate_args(dir, "cc1", "plate"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = slurp(dir / "plate.html");
  EXPECT_NE(page.find("<title>ncbridge CC1: plate.ngc</title>"), std::string::npos);
  // The plate's CC1 model: its workingsteps (milling, each a TOOLPATH_FEATURE, and four drilling
  // cycles on ROUND_HOLEs); the holes outlined, every workingstep tied to its feature.
  const auto wsf = workingstep_features(page);
  EXPECT_EQ(wsf.size(), 10u);
  for (int f : wsf) EXPECT_GE(f, 0);
  EXPECT_EQ(occurrences(page, "class=\"ol\" data-k="), 4u);
  EXPECT_NE(page.find("toolpath_feature (6)"), std::string::npos);
  EXPECT_NE(page.find("round_hole (4)"), std::string::npos);
  EXPECT_GT(occurrences(page, "<polyline class=\"cut\""), 0u);
  // The same model as without the page: the streamed and the whole-model writer agree.
  const fs::path plain = fresh_directory("cc1_plain");
  std::vector<std::string> args = plate_args(plain, "cc1", "plate");
  args.resize(args.size() - 2);
  ASSERT_EQ(ncbridge(args).exit_code, 0);
  EXPECT_EQ(slurp(plain / "plate.stp"), slurp(dir / "plate.stp"));
}

TEST(HtmlPage, AGeneratedCc1ModelIsDrawnOnTheFeaturesOfItsCc2File) {
  const fs::path dir = fresh_directory("generated");
  ASSERT_EQ(ncbridge(plate_args(dir, "cc2", "plate_cc2")).exit_code, 0);
  const ProgramRun r = ncbridge({"convert", (dir / "plate_cc2.stp").string(), "--level", "cc1", "-o", (dir / "gen.stp").string(),
                                 "--html", (dir / "gen.html").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string cc2_page = slurp(dir / "plate_cc2.html");
  const std::string page = slurp(dir / "gen.html");
  EXPECT_NE(page.find("<title>ncbridge CC1: plate_cc2.stp</title>"), std::string::npos);
  // The six CC2 features outlined (a face, a pocket, four holes), as on the CC2 page.
  EXPECT_EQ(occurrences(page, "class=\"ol\" data-k="), 6u);
  EXPECT_EQ(occurrences(cc2_page, "class=\"ol\" data-k="), 6u);
  for (const char* feature : {"PLANAR FACE1", "POCKET1", "HOLE1 D=6MM", "HOLE4 D=6MM"}) {
    EXPECT_NE(page.find(std::string("<title>") + feature + " ("), std::string::npos) << feature;
  }
  // Each generated workingstep is the CC2 file's, on its feature, with the strategy it states.
  const auto wsf = workingstep_features(page);
  EXPECT_EQ(wsf, workingstep_features(cc2_page));
  EXPECT_EQ(wsf.size(), 6u);
  for (int f : wsf) EXPECT_GE(f, 0);
  EXPECT_NE(page.find("bottom_and_side_rough_milling T2 END_MILL_D8 (contour_parallel)"), std::string::npos);
  // Generated toolpaths: more cutting moves than a drill's points.
  EXPECT_GT(occurrences(page, "<polyline class=\"cut\""), 6u);
}

TEST(HtmlPage, APlanIsDrawnWithItsGeneratedToolpaths) {
  const fs::path dir = fresh_directory("plan");
  const ProgramRun r = ncbridge({"plan", (kPart / "bracket.step").string(), "--stock", (kPart / "stock.json").string(), "--tools",
                                 (kPart / "tools.json").string(), "-o", (dir / "b.stp").string(), "--html", (dir / "b.html").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = slurp(dir / "b.html");
  const auto wsf = workingstep_features(page);
  ASSERT_FALSE(wsf.empty());
  for (int f : wsf) EXPECT_GE(f, 0);
  EXPECT_GT(occurrences(page, "<polyline class=\"cut\""), wsf.size());
  EXPECT_EQ(page.find("toolpaths not generated"), std::string::npos);
}

}  // namespace
}  // namespace ncbridge::cli

namespace ncbridge::cli {
namespace {

const fs::path kArcs = fs::path(NCBRIDGE_SHARED_DIR) / "corpus" / "arcs";

// The body's data-layer-counts: motions before, lines and arcs after, in the layer drawn.
std::vector<int> layer_counts(const std::string& page) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(page, m, std::regex("data-layer-counts=\"([0-9]+) ([0-9]+) ([0-9]+)\"")));
  return {std::stoi(m[1].str()), std::stoi(m[2].str()), std::stoi(m[3].str())};
}

std::string chosen_layer(const std::string& page) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(page, m, std::regex("<body[^>]* data-layer=\"([0-9]+)\"")));
  return m[1].str();
}

TEST(OptimizeHtmlPage, TheCylindersMiddleLayerComesDownToAFewArcs) {
  const fs::path dir = fresh_directory("optimize_cylinder");
  const ProgramRun r = ncbridge({"optimize", (kArcs / "slic3r129_cylinder.gcode").string(), "--flavor", "marlin", "-o",
                                 (dir / "c.gcode").string(), "--html", (dir / "c.html").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = slurp(dir / "c.html");
  // 100 layers (0.3 mm, the first at 0.2): the middle one is the 50th, at Z 15; a polygonal circle of ~150 motions becomes
  // a handful of arcs (three perimeters) and short lines.
  EXPECT_NE(page.find("layer 50 of 100, Z 15 mm"), std::string::npos);
  const auto counts = layer_counts(page);
  EXPECT_GT(counts[0], 100);
  EXPECT_GE(counts[2], 3);
  EXPECT_LT(counts[1] + counts[2], counts[0] / 10);
  EXPECT_EQ(occurrences(page, "<polyline class=\"arc\""), static_cast<std::size_t>(counts[2]));
  EXPECT_EQ(page.find("<script src"), std::string::npos);
}

TEST(OptimizeHtmlPage, ALayerIsChosenByNumberOrZAndAMissingOneIsAUsageErrorWithNothingWritten) {
  const fs::path dir = fresh_directory("optimize_layers");
  const std::string program = (kArcs / "slic3r129_cylinder.gcode").string();
  auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args{"optimize", program, "--flavor", "marlin", "-o", (dir / "c.gcode").string(), "--html",
                                  (dir / "c.html").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return ncbridge(args);
  };
  ASSERT_EQ(run({"--html-layer", "1"}).exit_code, 0);
  EXPECT_EQ(chosen_layer(slurp(dir / "c.html")), "1");
  ASSERT_EQ(run({"--html-z", "3"}).exit_code, 0);
  EXPECT_NE(slurp(dir / "c.html").find(", Z 3 mm"), std::string::npos);
  fs::remove(dir / "c.html");
  fs::remove(dir / "c.gcode");
  const ProgramRun missing = run({"--html-layer", "500"});
  EXPECT_EQ(missing.exit_code, 2) << missing.err;
  EXPECT_NE(missing.err.find("--html-layer 500: the program has 100 layers"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(dir / "c.html"));
  EXPECT_FALSE(fs::exists(dir / "c.gcode"));
  const ProgramRun no_z = run({"--html-z", "3.33"});
  EXPECT_EQ(no_z.exit_code, 2) << no_z.err;
  EXPECT_NE(no_z.err.find("no layer at that Z"), std::string::npos) << no_z.err;
  EXPECT_EQ(ncbridge({"optimize", program, "--flavor", "marlin", "-o", (dir / "c.gcode").string(), "--html-layer", "2"}).exit_code, 2);
}

TEST(OptimizeHtmlPage, ACncProgramsLayerIsDrawnFromItsDialectsOutput) {
  const fs::path dir = fresh_directory("optimize_cnc");
  const ProgramRun r = ncbridge({"optimize", (fs::path(NCBRIDGE_SOURCE_DIR) / "examples" / "optimize" / "pocket_wall.ngc").string(),
                                 "--dialect", "rs274ngc", "--to", "fanuc", "-o", (dir / "p.nc").string(), "--html", (dir / "p.html").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto counts = layer_counts(slurp(dir / "p.html"));
  EXPECT_GT(counts[0], 50);
  EXPECT_GE(counts[2], 1);
  EXPECT_LT(counts[1] + counts[2], counts[0]);
}

}  // namespace
}  // namespace ncbridge::cli

namespace ncbridge::cli {
namespace {

TEST(HtmlPage, GcodeDrawsTheToolpathsOfTheProgramItWritesFromAStepncFile) {
  const fs::path dir = fresh_directory("gcode");
  ASSERT_EQ(ncbridge(plate_args(dir, "cc2", "plate_cc2")).exit_code, 0);
  const ProgramRun r = ncbridge({"gcode", (dir / "plate_cc2.stp").string(), "--to", "fanuc", "-o", (dir / "p.nc").string(), "--html",
                                 (dir / "g.html").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = slurp(dir / "g.html");
  EXPECT_EQ(occurrences(page, "class=\"ol\" data-k="), 6u);
  EXPECT_EQ(workingstep_features(page), workingstep_features(slurp(dir / "plate_cc2.html")));
  EXPECT_NE(page.find("does not break through"), std::string::npos);  // the generator's warnings, on the page too
  // A program is translated, not modelled: the page is convert's; nothing is written.
  const ProgramRun program = ncbridge({"gcode", (kPlate / "plate.ngc").string(), "--tools", (kPlate / "tools.json").string(), "--to",
                                       "fanuc", "-o", (dir / "q.nc").string(), "--html", (dir / "q.html").string()});
  EXPECT_EQ(program.exit_code, 2) << program.err;
  EXPECT_NE(program.err.find("convert PROGRAM --level cc1 --html"), std::string::npos) << program.err;
  EXPECT_FALSE(fs::exists(dir / "q.nc"));
  EXPECT_FALSE(fs::exists(dir / "q.html"));
}

// The documentation's CC2 examples (docs/toolpaths.md, "Pictures") generate without a warning,
// each workingstep on its feature, every feature outlined.
TEST(HtmlPage, TheToolpathExamplesGenerateCleanly) {
  const fs::path dir = fresh_directory("examples");
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(NCBRIDGE_SOURCE_DIR) / "examples" / "toolpaths")) {
    if (entry.path().extension() != ".stp") continue;
    ++files;
    const std::string name = entry.path().stem().string();
    const ProgramRun r = ncbridge({"convert", entry.path().string(), "--level", "cc1", "-o", (dir / (name + ".stp")).string(),
                                   "--html", (dir / (name + ".html")).string()});
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    EXPECT_EQ(r.err.find("ncbridge: warning"), std::string::npos) << name << ": " << r.err;
    const std::string page = slurp(dir / (name + ".html"));
    const auto wsf = workingstep_features(page);
    ASSERT_FALSE(wsf.empty()) << name;
    for (int f : wsf) EXPECT_GE(f, 0) << name;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(page, m, std::regex("\"fk\":\\[([0-9,]*)\\]"))) << name;
    const std::string kinds = m[1].str();
    const std::size_t features = static_cast<std::size_t>(std::count(kinds.begin(), kinds.end(), ',') + 1);
    EXPECT_EQ(occurrences(page, "class=\"ol\" data-k="), features) << name;
    EXPECT_GT(occurrences(page, "<polyline class=\"cut\""), 0u) << name;
  }
  EXPECT_EQ(files, 9u);
}

}  // namespace
}  // namespace ncbridge::cli
