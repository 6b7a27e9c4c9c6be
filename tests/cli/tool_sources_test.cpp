// convert takes the tool data shops have: the plate converted with its tools as a LinuxCNC tool
// table (--tool-table), a Fusion 360 library export, a tool list in inches and a FreeCAD library
// gives the same STEP-NC as with examples/plate/tools.json (ncbridge diff: identical).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_program.hpp"

namespace ncbridge::cli {
namespace {

namespace fs = std::filesystem;
using ncbridge::testing::ProgramRun;

const fs::path kPlate = fs::path(NCBRIDGE_SOURCE_DIR) / "examples" / "plate";

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = fs::path(NCBRIDGE_BINARY_DIR) / "test_output" / "cli" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

ProgramRun ncbridge(std::vector<std::string> args) {
  args.insert(args.begin(), NCBRIDGE_EXECUTABLE);
  return ncbridge::testing::run_program(args, {{}, {"SOURCE_DATE_EPOCH=1700000000"}, false});
}

fs::path convert(const fs::path& dir, const std::string& name, std::vector<std::string> tool_args) {
  std::vector<std::string> args{"convert", (kPlate / "plate.ngc").string(), "--stock", (kPlate / "stock.json").string(),
                                "--level", "cc2", "-o", (dir / (name + ".stp")).string()};
  args.insert(args.end(), tool_args.begin(), tool_args.end());
  const ProgramRun r = ncbridge(args);
  EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
  return dir / (name + ".stp");
}

// ncbridge diff's report names each entity type that differs on a line of its own, and each
// instance only in one file as "#N TYPE(...)": only the tools' entities may appear.
void expect_only_tools_differ(const std::string& report) {
  const std::set<std::string> tool_entities{"MILLING_CUTTING_TOOL", "MILLING_TOOL_DIMENSION", "FACEMILL", "ENDMILL",
                                            "TWIST_DRILL", "USER_DEFINED_TOOL"};
  const std::regex header("^([A-Z][A-Z0-9_]+)$");
  const std::regex instance("^  #[0-9]+ ([A-Z][A-Z0-9_]+)\\(");
  std::istringstream lines(report);
  int seen = 0;
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (std::regex_match(line, m, header) || std::regex_search(line, m, instance)) {
      ++seen;
      EXPECT_TRUE(tool_entities.contains(m[1].str())) << "not a tool's entity: " << line << "\n" << report;
    }
  }
  EXPECT_GT(seen, 0) << report;
}

TEST(ToolSources, EveryFormatConvertsThePlateAsItsToolList) {
  const fs::path dir = fresh_directory("tool_sources");
  const fs::path reference = convert(dir, "json", {"--tools", (kPlate / "tools.json").string()});
  struct Source {
    std::string name;
    std::vector<std::string> args;
  };
  for (const Source& s : std::vector<Source>{
           {"fusion", {"--tools", (kPlate / "tools_fusion.json").string()}},
           {"inch", {"--tools", (kPlate / "tools_inch.yaml").string()}}}) {
    const fs::path file = convert(dir, s.name, s.args);
    const ProgramRun diff = ncbridge({"diff", reference.string(), file.string(), "--tolerance", "0.001"});
    EXPECT_EQ(diff.exit_code, 0) << s.name << ":\n" << diff.out << diff.err;
  }
  // A LinuxCNC tool table has no tool kinds (user-defined tools), and FreeCAD no face mill (the
  // facing tool is an end mill there): the tools differ, the features and toolpaths do not.
  const fs::path table = convert(dir, "tool_table", {"--tool-table", (kPlate / "tools.tbl").string(), "--tool-table-units", "inch"});
  const ProgramRun table_diff = ncbridge({"diff", reference.string(), table.string(), "--tolerance", "0.001"});
  EXPECT_EQ(table_diff.exit_code, 5) << table_diff.out << table_diff.err;
  expect_only_tools_differ(table_diff.out);
  const fs::path freecad = convert(dir, "freecad", {"--tools", (kPlate / "freecad" / "Library" / "plate.fctl").string()});
  const ProgramRun freecad_diff = ncbridge({"diff", reference.string(), freecad.string()});
  EXPECT_EQ(freecad_diff.exit_code, 5) << freecad_diff.out << freecad_diff.err;
  EXPECT_NE(freecad_diff.out.find("FACEMILL"), std::string::npos) << freecad_diff.out;
  expect_only_tools_differ(freecad_diff.out);
}

TEST(ToolSources, OneToolListAndClearErrors) {
  const fs::path dir = fresh_directory("tool_sources_errors");
  const ProgramRun both = ncbridge({"convert", (kPlate / "plate.ngc").string(), "--stock", (kPlate / "stock.json").string(),
                                    "--tools", (kPlate / "tools.json").string(), "--tool-table", (kPlate / "tools.tbl").string(),
                                    "-o", (dir / "x.stp").string()});
  EXPECT_EQ(both.exit_code, 2) << both.err;
  EXPECT_NE(both.err.find("give one tool list"), std::string::npos) << both.err;
  const ProgramRun table_as_list = ncbridge({"convert", (kPlate / "plate.ngc").string(), "--stock", (kPlate / "stock.json").string(),
                                             "--tools", (kPlate / "tools.tbl").string(), "-o", (dir / "x.stp").string()});
  EXPECT_EQ(table_as_list.exit_code, 1) << table_as_list.err;
  EXPECT_NE(table_as_list.err.find("give it with --tool-table"), std::string::npos) << table_as_list.err;
  EXPECT_FALSE(fs::exists(dir / "x.stp"));
}

// plan takes a LinuxCNC tool table: the tools' kinds read from their comments, the bracket is
// planned as with examples/part/tools.json (the same workingsteps, operations, features and
// tools); a tool whose comment names no kind is said in a warning, and not used.
TEST(ToolSources, PlanWithAToolTablePlansAsWithTheToolList) {
  const fs::path dir = fresh_directory("plan_tool_table");
  const fs::path part = fs::path(NCBRIDGE_SOURCE_DIR) / "examples" / "part";
  std::ofstream(dir / "shop.tbl") << "T1 P1 D50 Z50 ;FACE_MILL_D50\n"
                                     "T2 P2 D16 Z75 ;END_MILL_D16\n"
                                     "T3 P3 D12 Z70 ;end mill 12\n"
                                     "T4 P4 D6 Z60 ;Endmill 6mm\n"
                                     "T5 P5 D10 Z60 ;SPOT_D10\n"
                                     "T6 P6 D6 Z70 ;DRILL_D6\n"
                                     "T7 P7 D8.5 Z90 ;drill 8.5\n"
                                     "T8 P8 D11 Z100 ;DRILL-D11\n"
                                     "T9 P9 D25 Z90 ;END_MILL_D25\n"
                                     "T10 P10 D3 Z40 ;SPARE\n";
  const auto plan = [&](const std::string& name, std::vector<std::string> tools) {
    std::vector<std::string> args{"plan", (part / "bracket.step").string(), "--stock", (part / "stock.json").string(),
                                  "-o", (dir / (name + ".stp")).string(), "--report", (dir / (name + ".json")).string()};
    args.insert(args.end(), tools.begin(), tools.end());
    const ProgramRun r = ncbridge(args);
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
    std::vector<std::string> steps;
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(dir / (name + ".json")));
    for (const auto& w : report.at("workingsteps")) {
      std::string tool = w["tool"].get<std::string>();
      tool = tool.substr(0, tool.find(' '));  // the number: the names differ
      steps.push_back(w["id"].get<std::string>() + " " + w["operation"].get<std::string>() + " " + tool);
    }
    return std::make_pair(steps, r.err);
  };
  const auto [with_table, table_err] = plan("table", {"--tool-table", (dir / "shop.tbl").string()});
  const auto [with_list, list_err] = plan("list", {"--tools", (part / "tools.json").string()});
  EXPECT_GT(with_list.size(), 10u);
  EXPECT_EQ(with_table, with_list);
  EXPECT_NE(table_err.find("shop.tbl: tool T10 (\"SPARE\"): its comment names no kind of tool"), std::string::npos) << table_err;
  EXPECT_EQ(table_err.find("T3"), std::string::npos) << table_err;

  const ProgramRun both = ncbridge({"plan", (part / "bracket.step").string(), "--tools", (part / "tools.json").string(),
                                    "--tool-table", (dir / "shop.tbl").string(), "-o", (dir / "x.stp").string()});
  EXPECT_EQ(both.exit_code, 2) << both.err;
  const ProgramRun none = ncbridge({"plan", (part / "bracket.step").string(), "-o", (dir / "x.stp").string()});
  EXPECT_EQ(none.exit_code, 2) << none.err;
  EXPECT_FALSE(fs::exists(dir / "x.stp"));
}

}  // namespace
}  // namespace ncbridge::cli
