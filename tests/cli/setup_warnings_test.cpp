// Warnings that catch a wrong setup (cli/src/setup_checks.hpp, docs/cli.md#warnings): each is
// on stderr, in the JSON report (with its kind) and on the HTML page, and --strict makes it an
// error that writes nothing. Right setups (the corpus' CAM parts, the plate) give none.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
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
const fs::path kCam = fs::path(NCBRIDGE_SHARED_DIR) / "corpus" / "cam";
const char* const kSetupKinds[] = {"feed", "outside_stock", "security_plane", "units", "tool_type"};

fs::path fresh_directory(const std::string& name) { return ncbridge::testing::fresh_test_directory("cli_setup_warnings", name); }

using ncbridge::testing::slurp;

ProgramRun ncbridge(std::vector<std::string> args) {
  args.insert(args.begin(), NCBRIDGE_EXECUTABLE);
  return ncbridge::testing::run_program(args, {{}, {"SOURCE_DATE_EPOCH=1700000000"}, false});
}

// The warnings of one kind in a report.
std::vector<nlohmann::json> of_kind(const nlohmann::json& report, const std::string& kind) {
  std::vector<nlohmann::json> found;
  for (const auto& w : report.at("warnings")) {
    if (w.at("kind") == kind) found.push_back(w);
  }
  return found;
}

struct Converted {
  ProgramRun run;
  nlohmann::json report;
};

// `convert` with a report; the warnings of `kind` must be on stderr as well.
Converted convert(const fs::path& dir, std::vector<std::string> args) {
  args.insert(args.begin(), "convert");
  args.insert(args.end(), {"-o", (dir / "out.stp").string(), "--report", (dir / "out.json").string()});
  Converted c{ncbridge(args), {}};
  EXPECT_EQ(c.run.exit_code, 0) << c.run.err;
  if (c.run.exit_code == 0) c.report = nlohmann::json::parse(slurp(dir / "out.json"));
  return c;
}

void expect_on_stderr(const Converted& c, const std::string& kind, std::size_t count) {
  std::size_t lines = 0;
  for (std::size_t at = 0; (at = c.run.err.find("[" + kind + "]\n", at)) != std::string::npos; ++at) ++lines;
  EXPECT_EQ(lines, count) << c.run.err;
}

// --strict: the same run exits 1, says why, and writes nothing.
void expect_strict_refuses(const fs::path& dir, std::vector<std::string> args, const std::string& kind) {
  args.insert(args.begin(), "convert");
  args.insert(args.end(), {"-o", (dir / "strict.stp").string(), "--report", (dir / "strict.json").string(), "--strict"});
  const ProgramRun r = ncbridge(args);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("[" + kind + "]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("with --strict: nothing written"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "strict.stp"));
  EXPECT_FALSE(fs::exists(dir / "strict.json"));
}

std::vector<std::string> plate_args(const fs::path& stock, const fs::path& tools = kPlate / "tools.json") {
  return {(kPlate / "plate.ngc").string(), "--tools", tools.string(), "--stock", stock.string()};
}

TEST(SetupWarnings, AHeidenhainProgramPostedInMmPerSecondIsCaughtByItsFeeds) {
  // FreeCAD's Heidenhain post writes mm/s; read as the control's mm/min, every feed is 60x too slow.
  const fs::path part = kCam / "p03_bracket_steps";
  const fs::path dir = fresh_directory("heidenhain_feeds");
  const std::vector<std::string> args{(part / "part.heidenhain.h").string(), "--dialect", "heidenhain", "--tools",
                                      (part / "tools.json").string(), "--stock", (part / "stock.json").string()};
  const Converted wrong = convert(dir, args);
  const auto feeds = of_kind(wrong.report, "feed");
  ASSERT_GE(feeds.size(), 4u) << wrong.run.err;
  for (const auto& w : feeds) {
    const std::string message = w.at("message");
    EXPECT_NE(message.find("implausibly slow"), std::string::npos) << message;
    EXPECT_NE(message.find("60 times that would be plausible"), std::string::npos) << message;
    EXPECT_NE(message.find("--heidenhain-feed-units mm/s"), std::string::npos) << message;
    EXPECT_NE(std::string(w.at("where")).find("part.heidenhain.h:"), std::string::npos) << w;
  }
  expect_on_stderr(wrong, "feed", feeds.size());
  expect_strict_refuses(dir, args, "feed");

  std::vector<std::string> right = args;
  right.insert(right.end(), {"--heidenhain-feed-units", "mm/s"});
  EXPECT_TRUE(of_kind(convert(dir, right).report, "feed").empty());

  // The same program posted for LinuxCNC, in mm/min: plausible.
  EXPECT_TRUE(of_kind(convert(dir, {(part / "part.nc").string(), "--tools", (part / "tools.json").string(), "--stock",
                                    (part / "stock.json").string()})
                          .report,
                      "feed")
                  .empty());
}

TEST(SetupWarnings, ToolpathsOutsideTheStockAreNamedWithTheirWorkingstepAndSide) {
  const fs::path dir = fresh_directory("outside_stock");
  std::ofstream(dir / "shifted.json") << R"({"min": [300, 0, -20], "max": [380, 60, 2]})";
  const Converted c = convert(dir, plate_args(dir / "shifted.json"));
  const auto outside = of_kind(c.report, "outside_stock");
  ASSERT_FALSE(outside.empty()) << c.run.err;
  EXPECT_NE(std::string(outside[0].at("message")).find("beyond the stock's x- side (X300)"), std::string::npos) << outside[0];
  EXPECT_NE(std::string(outside[0].at("where")).find("plate.ngc:"), std::string::npos) << outside[0];
  expect_on_stderr(c, "outside_stock", outside.size());
  expect_strict_refuses(dir, plate_args(dir / "shifted.json"), "outside_stock");

  std::ofstream(dir / "thin.json") << R"({"min": [0, 0, -10], "max": [80, 60, 2]})";  // the holes go to Z-22
  const auto below = of_kind(convert(dir, plate_args(dir / "thin.json")).report, "outside_stock");
  ASSERT_FALSE(below.empty());
  EXPECT_NE(std::string(below[0].at("message")).find("below the stock's bottom (Z-10)"), std::string::npos) << below[0];
}

TEST(SetupWarnings, ASecurityPlaneInsideOrBelowTheStock) {
  const fs::path dir = fresh_directory("security_plane");
  std::vector<std::string> args = plate_args(kPlate / "stock.json");
  args.insert(args.end(), {"--security-plane", "-30"});
  const auto below = of_kind(convert(dir, args).report, "security_plane");
  ASSERT_EQ(below.size(), 1u);
  EXPECT_NE(std::string(below[0].at("message")).find("--security-plane -30) is below the stock (Z-20 to Z2)"), std::string::npos)
      << below[0];
  args.back() = "-5";
  const auto inside = of_kind(convert(dir, args).report, "security_plane");
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_NE(std::string(inside[0].at("message")).find("is inside the stock"), std::string::npos) << inside[0];
  expect_strict_refuses(dir, args, "security_plane");
  // The program's own (its highest rapid, Z10) is above the stock top (Z2): nothing to say.
  EXPECT_TRUE(of_kind(convert(dir, plate_args(kPlate / "stock.json")).report, "security_plane").empty());
}

TEST(SetupWarnings, AnInchProgramWithAMillimetreStock) {
  const fs::path dir = fresh_directory("units");
  std::ofstream(dir / "inch.ngc") << "G20 G17 G40 G49 G54 G80 G90 G94\nT1 M6\nG43 H1\nS5000 M3\nG0 X-0.5 Y0.5 Z0.5\n"
                                     "G0 Z0.1\nG1 Z-0.1 F10\nG1 X3.5 F40\nG0 Z0.5\nM30\n";
  std::ofstream(dir / "tools.json") << R"([{"number": 1, "type": "flat_end_mill", "diameter": 6.35, "length": 50, "flutes": 2}])";
  std::ofstream(dir / "stock_mm.json") << R"({"min": [0, 0, -0.5], "max": [3, 1, 0]})";  // inch numbers, no units
  std::ofstream(dir / "stock_inch.json") << R"({"units": "inch", "min": [0, 0, -0.5], "max": [3, 1, 0]})";
  const std::vector<std::string> args{(dir / "inch.ngc").string(), "--tools", (dir / "tools.json").string(), "--stock",
                                      (dir / "stock_mm.json").string()};
  const Converted wrong = convert(dir, args);
  const auto units = of_kind(wrong.report, "units");
  ASSERT_EQ(units.size(), 1u) << wrong.run.err;
  EXPECT_EQ(units[0].at("where"), (dir / "inch.ngc").string() + ":1");
  EXPECT_NE(std::string(units[0].at("message")).find("the program cuts in inches (G20) but the stock"), std::string::npos);
  EXPECT_NE(std::string(units[0].at("message")).find("add \"units\": \"inch\""), std::string::npos);
  EXPECT_FALSE(of_kind(wrong.report, "outside_stock").empty());  // 25.4 times too small a stock
  expect_strict_refuses(dir, args, "units");

  const Converted right = convert(dir, {(dir / "inch.ngc").string(), "--tools", (dir / "tools.json").string(), "--stock",
                                        (dir / "stock_inch.json").string()});
  EXPECT_TRUE(of_kind(right.report, "units").empty()) << right.run.err;
  EXPECT_TRUE(of_kind(right.report, "outside_stock").empty()) << right.run.err;
}

TEST(SetupWarnings, AToolWithoutAType) {
  const fs::path dir = fresh_directory("tool_type");
  std::ofstream(dir / "tools.json")
      << R"([{"number": 1, "name": "FACE_MILL_D50", "type": "face_mill", "diameter": 50, "length": 45, "flutes": 5},
             {"number": 2, "name": "MYSTERY_D8", "diameter": 8, "length": 55},
             {"number": 3, "name": "DRILL_D6", "type": "drill", "diameter": 6, "length": 70}])";
  const Converted c = convert(dir, plate_args(kPlate / "stock.json", dir / "tools.json"));
  const auto untyped = of_kind(c.report, "tool_type");
  ASSERT_EQ(untyped.size(), 1u) << c.run.err;
  EXPECT_EQ(untyped[0].at("where"), (dir / "tools.json").string());
  EXPECT_NE(std::string(untyped[0].at("message")).find("tool 2 (MYSTERY_D8) has no \"type\""), std::string::npos);
  expect_strict_refuses(dir, plate_args(kPlate / "stock.json", dir / "tools.json"), "tool_type");
}

TEST(SetupWarnings, TheHtmlPageShowsThemFirst) {
  const fs::path dir = fresh_directory("html");
  std::vector<std::string> args = plate_args(kPlate / "stock.json");
  args.insert(args.end(), {"--level", "cc2", "--security-plane", "-5", "-o", (dir / "p.stp").string(), "--html",
                           (dir / "p.html").string()});
  args.insert(args.begin(), "convert");
  const ProgramRun r = ncbridge(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = slurp(dir / "p.html");
  const auto box = page.find("<div class=\"setup\"><h2>Check the setup (1 warning)</h2>");
  ASSERT_NE(box, std::string::npos);
  EXPECT_LT(box, page.find("<h2>Features"));
  EXPECT_NE(page.find("is inside the stock", box), std::string::npos);
}

TEST(SetupWarnings, RightSetupsGiveNone) {
  const fs::path dir = fresh_directory("right_setups");
  std::vector<std::vector<std::string>> runs{plate_args(kPlate / "stock.json")};
  for (const char* part : {"p01_block_reference", "p02_plate_center_zero", "p03_bracket_steps", "p04_open_pockets", "p05_slots"}) {
    const fs::path p = kCam / part;
    const fs::path program = fs::exists(p / "part.linuxcnc.ngc") ? p / "part.linuxcnc.ngc" : p / "part.nc";
    const std::string tools = (p / "tools.json").string(), stock = (p / "stock.json").string();
    runs.push_back({program.string(), "--tools", tools, "--stock", stock});
    runs.push_back({(p / "part.heidenhain.h").string(), "--dialect", "heidenhain", "--heidenhain-feed-units", "mm/s",
                    "--tools", tools, "--stock", stock});
    if (fs::exists(p / "part.fanuc.nc")) runs.push_back({(p / "part.fanuc.nc").string(), "--dialect", "fanuc", "--tools", tools, "--stock", stock});
  }
  for (const auto& args : runs) {
    const Converted c = convert(dir, args);
    for (const char* kind : kSetupKinds) EXPECT_TRUE(of_kind(c.report, kind).empty()) << args[0] << ": " << c.run.err;
  }
}

TEST(SetupWarnings, ACoarseDiffToleranceIsSaid) {
  const fs::path dir = fresh_directory("tolerance");
  ASSERT_EQ(ncbridge({"convert", (kPlate / "plate.ngc").string(), "--tools", (kPlate / "tools.json").string(), "--stock",
                      (kPlate / "stock.json").string(), "-o", (dir / "a.stp").string()})
                .exit_code,
            0);
  const ProgramRun coarse = ncbridge({"diff", (dir / "a.stp").string(), (dir / "a.stp").string(), "--tolerance", "5"});
  EXPECT_EQ(coarse.exit_code, 0);
  EXPECT_NE(coarse.err.find("ncbridge: warning: --tolerance 5 mm is coarser than any machining tolerance"), std::string::npos)
      << coarse.err;
  const ProgramRun fine = ncbridge({"diff", (dir / "a.stp").string(), (dir / "a.stp").string(), "--tolerance", "0.01"});
  EXPECT_TRUE(fine.err.empty()) << fine.err;
}

}  // namespace
}  // namespace ncbridge::cli
