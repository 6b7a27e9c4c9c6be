// `ncbridge plan` on the five CAM parts of the shared corpus (FreeCAD's part.step): the report's
// features are the truth's (F1 = 1.0 with centres and sizes within 0.05 mm and depths exact),
// the CC2 file passes the schema check. Each part is placed in its stock as its stock.json says
// (part_bbox_min): four of the five STEP files are not in the program frame.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cam_truth.hpp"
#include "ncbridge/material_check/material_check.hpp"
#include "ncbridge/material_check/toolpath_program.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/toolpath_generator/toolpath_generator.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kShared = NCBRIDGE_SHARED_DIR;
const fs::path kNcbridge = fs::path(NCBRIDGE_BINARY_DIR) / "bin" / "ncbridge";

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int run(const std::string& arguments, const fs::path& err) {
  const std::string command = "SOURCE_DATE_EPOCH=1700000000 '" + kNcbridge.string() + "' " + arguments + " 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class CamPart : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(CamPart, PlanFindsTheTruthsFeaturesInTheStep) {
  const fs::path part = kShared / "corpus" / "cam" / GetParam();
  const fs::path dir = fs::temp_directory_path() / ("ncbridge_plan_cam_" + GetParam());
  fs::remove_all(dir);
  fs::create_directories(dir);
  const int code = run("plan '" + (part / "part.step").string() + "' --stock '" + (part / "stock.json").string() + "' --tools '" +
                           (part / "tools.json").string() + "' -o '" + (dir / "cc2.stp").string() + "' --report '" +
                           (dir / "report.json").string() + "' --html '" + (dir / "page.html").string() + "'",
                       dir / "err.txt");
  ASSERT_EQ(code, 0) << read_file(dir / "err.txt");
  const auto report = nlohmann::json::parse(read_file(dir / "report.json"));
  const auto truth = nlohmann::json::parse(read_file(part / "truth.json"));
  const auto score = ncbridge::testing::score_against_truth(report["features"], truth["features"]);
  std::string missed;
  for (const auto& u : score.unmatched) missed += "\n  " + u;
  EXPECT_EQ(score.matched, score.truth) << missed;
  EXPECT_EQ(score.reported, score.truth) << report["features"].dump(1);
  EXPECT_DOUBLE_EQ(score.f1(), 1.0);
  EXPECT_EQ(run("check '" + (dir / "cc2.stp").string() + "'", dir / "check.txt"), 0) << read_file(dir / "check.txt");
  EXPECT_NE(read_file(dir / "check.txt").find(", 0 errors, 0 warnings"), std::string::npos) << read_file(dir / "check.txt");
}

// The plan goes on to a program that makes the part: its CC2 file's toolpaths generated
// (services/toolpath_generator) and simulated on the stock (common/material_check): nothing
// cut below the design, no rapid through material, no plunge, every feature cut to its design.
TEST_P(CamPart, ThePlannedProgramMakesThePart) {
  namespace mc = ncbridge::material_check;
  const fs::path part = kShared / "corpus" / "cam" / GetParam();
  const fs::path dir = fs::temp_directory_path() / ("ncbridge_plan_cam_made_" + GetParam());
  fs::remove_all(dir);
  fs::create_directories(dir);
  const int code = run("plan '" + (part / "part.step").string() + "' --stock '" + (part / "stock.json").string() + "' --tools '" +
                           (part / "tools.json").string() + "' -o '" + (dir / "cc2.stp").string() + "'",
                       dir / "err.txt");
  ASSERT_EQ(code, 0) << read_file(dir / "err.txt");
  const auto cc2 = ncbridge::step_writer::read_stepnc_file(dir / "cc2.stp").project;
  const auto stock = ncbridge::setup::read_stock((part / "stock.json").string());
  ncbridge::toolpath_generator::Options options;
  options.stock = stock;
  options.source_name = GetParam();
  const auto generated = ncbridge::toolpath_generator::generate_toolpaths(cc2, options);
  mc::CheckOptions check;
  check.cell = 0.2;
  const auto report = mc::check_material(mc::program_from_stepnc(generated.cc1), mc::designed_part(cc2, stock, GetParam()), check);
  std::printf("%-22s planned program: least reached %.4f, gouge %.4f mm, rapids through material %zu, plunges %zu, removed %.0f mm3\n",
              GetParam().c_str(), report.least_reached(), report.max_gouge, report.rapid_collisions, report.plunges,
              report.removed_volume);
  EXPECT_LE(report.max_gouge, 0.01) << "at " << report.max_gouge_at.x << " " << report.max_gouge_at.y << " " << report.max_gouge_at.z;
  EXPECT_EQ(report.rapid_collisions, 0u);
  EXPECT_EQ(report.plunges, 0u);
  const std::string warnings = read_file(dir / "err.txt");
  for (const auto& f : report.features) {
    // A flat-bottomed hole the tool list has no end mill to flatten: the plan says so, and the
    // drill's point is what is left (118 degrees: half its diameter / tan 59 deg).
    if (warnings.find(f.id + ": flat bottom: no flat end mill") != std::string::npos) {
      const double d = std::stod(f.id.substr(f.id.find("D=") + 2));
      EXPECT_LE(f.max_leftover, d / 2 / std::tan(59 * std::acos(-1.0) / 180) + 0.01) << f.id;
      continue;
    }
    EXPECT_GE(f.reached_fraction, 0.999) << f.id << ": leftover " << f.max_leftover << " mm";
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, CamPart,
                         ::testing::Values("p01_block_reference", "p02_plate_center_zero", "p03_bracket_steps", "p04_open_pockets",
                                           "p05_slots"));

TEST(CamTruthScore, ASizeOrCentreOffByMoreThanTheToleranceIsNotAMatch) {
  const auto truth = nlohmann::json::parse(read_file(kShared / "corpus" / "cam" / "p01_block_reference" / "truth.json"))["features"];
  nlohmann::json hole = {{"id", "HOLE1 D=10MM"}, {"type", "round_hole"}, {"center_xy", {75.0, 60.0}}, {"top_z", 30.0}, {"bottom_z", 0.0},
                         {"dimensions", {{"diameter", 10.0}}}};
  const nlohmann::json f6 = nlohmann::json::array({truth[5]});
  EXPECT_EQ(ncbridge::testing::score_against_truth(nlohmann::json::array({hole}), f6).matched, 1);
  auto moved = hole;
  moved["center_xy"] = {75.06, 60.0};
  EXPECT_EQ(ncbridge::testing::score_against_truth(nlohmann::json::array({moved}), f6).matched, 0);
  auto wider = hole;
  wider["dimensions"]["diameter"] = 10.06;
  EXPECT_EQ(ncbridge::testing::score_against_truth(nlohmann::json::array({wider}), f6).matched, 0);
  auto shallower = hole;
  shallower["bottom_z"] = 0.001;
  EXPECT_EQ(ncbridge::testing::score_against_truth(nlohmann::json::array({shallower}), f6).matched, 0);
}

TEST(CamStockStep, TheStockAsAStepSolid) {
  const fs::path dir = fs::temp_directory_path() / "ncbridge_plan_cam_stock_step";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // p01's part is modelled in its stock's frame: the stock solid is enough.
  const fs::path p01 = kShared / "corpus" / "cam" / "p01_block_reference";
  ASSERT_EQ(run("plan '" + (p01 / "part.step").string() + "' --stock-step '" + (p01 / "stock.step").string() + "' --tools '" +
                    (p01 / "tools.json").string() + "' -o '" + (dir / "p01.stp").string() + "' --report '" + (dir / "p01.json").string() + "'",
                dir / "err.txt"),
            0)
      << read_file(dir / "err.txt");
  const auto report = nlohmann::json::parse(read_file(dir / "p01.json"));
  EXPECT_EQ(report["stock"]["min"], nlohmann::json::array({-3.0, -3.0, 0.0}));
  EXPECT_EQ(report["stock"]["max"], nlohmann::json::array({103.0, 83.0, 32.0}));
  const auto truth = nlohmann::json::parse(read_file(p01 / "truth.json"));
  EXPECT_EQ(ncbridge::testing::score_against_truth(report["features"], truth["features"]).matched, 7);

  // p02's part is modelled at its corner, the stock around the program zero: refused until placed.
  const fs::path p02 = kShared / "corpus" / "cam" / "p02_plate_center_zero";
  const std::string args = "plan '" + (p02 / "part.step").string() + "' --stock-step '" + (p02 / "stock.step").string() + "' --tools '" +
                           (p02 / "tools.json").string() + "' -o '" + (dir / "p02.stp").string() + "' --report '" + (dir / "p02.json").string() + "'";
  EXPECT_EQ(run(args, dir / "err.txt"), 1);
  EXPECT_NE(read_file(dir / "err.txt").find("does not lie inside the stock"), std::string::npos) << read_file(dir / "err.txt");
  EXPECT_FALSE(fs::exists(dir / "p02.stp"));
  ASSERT_EQ(run(args + " --part-offset=-75,-50,-20", dir / "err.txt"), 0) << read_file(dir / "err.txt");
  const auto placed = nlohmann::json::parse(read_file(dir / "p02.json"));
  const auto truth2 = nlohmann::json::parse(read_file(p02 / "truth.json"));
  const auto score = ncbridge::testing::score_against_truth(placed["features"], truth2["features"]);
  EXPECT_EQ(score.matched, score.truth);
  EXPECT_EQ(score.reported, score.truth);
}
