// NIST's ISO 14649-11 example 1 (nist_ex1.stp: features and operations, no toolpath) given
// generated toolpaths: every workingstep gets its motion, the material check finds every feature
// cut and nothing else, and the removal is compared with NIST's own explicit-toolpath version of
// the same part (nist_ex1E.stp, what NIST's CAM made); and, by the material check, with the
// canonical calls NIST's STEP-NC interpreter made for the same features (nist_ex1.can): the same
// features cut by the same tools. All read in place from the shared corpus.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <regex>
#include <set>
#include <sstream>

#include "ncbridge/material_check/material_check.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/toolpath_generator/toolpath_generator.hpp"

namespace fs = std::filesystem;
namespace mc = ncbridge::material_check;
namespace tg = ncbridge::toolpath_generator;
using namespace ncbridge;

namespace {

const fs::path kStepnc = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/stepnc";

setup::Stock stock_of(const stepnc::Project& p) {
  const auto& b = *p.rawpiece->its_bounding_geometry;
  setup::Stock s;
  s.min = {b.position.location.x, b.position.location.y, b.position.location.z};
  s.max = {s.min[0] + b.x, s.min[1] + b.y, s.min[2] + b.z};
  return s;
}


// The motion of NIST's canonical calls (nist_ex1.can: `   14 STRAIGHT_TRAVERSE(91.9000, -13.5000,
// 200.0000)`, the XY plane, mm): one run per CHANGE_TOOL, with the shape of the tool of that name
// in nist_ex1.stp and drilling when a drilling-family operation of the file uses it. ARC_FEED's
// rotation is LinuxCNC's: its sign the sense (> 0 counter-clockwise), |rotation| - 1 whole turns
// more.
mc::ToolpathProgram program_from_nist_canon(const fs::path& file, const stepnc::Project& cc2) {
  std::map<std::string, std::size_t> tool_index;
  for (std::size_t i = 0; i < cc2.tools.size(); ++i) tool_index[cc2.tools[i].its_id] = i;
  std::set<std::size_t> drills;
  for (const auto& op : cc2.operations) {
    const auto name = stepnc::entity_name(op);
    if (name == "DRILLING" || name == "REAMING" || name == "MULTISTEP_DRILLING" || name == "CENTER_DRILLING" ||
        name == "BORING" || name == "TAPPING") {
      drills.insert(stepnc::machining_operation(op).its_tool.index);
    }
  }
  std::ifstream in(file);
  const std::regex call(R"(^\s*(\d+)\s+([A-Z_]+)\((.*)\)\s*$)");
  mc::ToolpathProgram program;
  mc::Point3 at{0, 0, 200};
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, call)) continue;
    const std::string name = m[2], args = m[3];
    if (name == "CHANGE_TOOL") {
      const auto found = tool_index.find(args);
      if (found == tool_index.end()) throw std::runtime_error("nist_ex1.can line " + m[1].str() + ": no tool '" + args + "' in nist_ex1.stp");
      mc::ToolRun run;
      run.workingstep = "nist_ex1.can line " + m[1].str();
      run.tool = args;
      run.cutter = mc::cutter_of(cc2.tools[found->second]);
      run.drilling = drills.count(found->second) > 0;
      run.start = at;
      program.runs.push_back(std::move(run));
      continue;
    }
    if (name != "STRAIGHT_TRAVERSE" && name != "STRAIGHT_FEED" && name != "ARC_FEED") continue;
    if (program.runs.empty()) throw std::runtime_error("nist_ex1.can line " + m[1].str() + ": a move before any CHANGE_TOOL");
    std::vector<double> v;
    std::stringstream list(args);
    for (std::string a; std::getline(list, a, ',');) v.push_back(std::stod(a));
    mc::Motion motion;
    if (name == "ARC_FEED") {
      if (v.size() != 6) throw std::runtime_error("nist_ex1.can line " + m[1].str() + ": ARC_FEED needs 6 arguments");
      motion.end = {v[0], v[1], v[5]};
      motion.arc_centre = mc::Point2{v[2], v[3]};
      const double turn = 2 * std::numbers::pi;
      double sweep = std::atan2(v[1] - v[3], v[0] - v[2]) - std::atan2(at.y - v[3], at.x - v[2]);
      const int rotation = static_cast<int>(v[4]);
      if (rotation > 0) {
        while (sweep <= 1e-9) sweep += turn;
        sweep += (rotation - 1) * turn;
      } else {
        while (sweep >= -1e-9) sweep -= turn;
        sweep -= (-rotation - 1) * turn;
      }
      motion.arc_sweep = sweep;
    } else {
      if (v.size() < 3) throw std::runtime_error("nist_ex1.can line " + m[1].str() + ": a move needs x, y, z");
      motion.rapid = name == "STRAIGHT_TRAVERSE";
      motion.end = {v[0], v[1], v[2]};
    }
    at = motion.end;
    program.runs.back().motions.push_back(motion);
  }
  return program;
}

// For each feature, the tools whose motion alone (on the stock as it comes) cuts some of it (1 %
// of its samples or more) to its design: the tools that make it. Not "most of it": NIST's drill
// stops where, with the point the material check reads from its tool_top_angle, it reaches only
// the middle of the through hole's bottom (docs/toolpaths.md).
std::map<std::string, std::set<std::string>> tools_per_feature(const mc::ToolpathProgram& program, const mc::DesignedPart& part,
                                                               const mc::CheckOptions& check) {
  std::map<std::string, mc::ToolpathProgram> by_tool;
  for (const auto& run : program.runs) by_tool[run.tool].runs.push_back(run);
  std::map<std::string, std::set<std::string>> out;
  for (const auto& [tool, alone] : by_tool) {
    for (const auto& f : mc::check_material(alone, part, check).features) {
      std::printf("    %s alone: %s reached %.4f\n", tool.c_str(), f.id.c_str(), f.reached_fraction);
      if (f.reached_fraction >= 0.01) out[f.id].insert(tool);
    }
  }
  return out;
}

std::string names(const std::set<std::string>& s) {
  std::string r;
  for (const auto& x : s) r += (r.empty() ? "" : ", ") + x;
  return r;
}

TEST(NistEx1, EveryWorkingstepGetsToolpathsThatCutItsFeature) {
  const auto cc2 = step_writer::read_stepnc_file(kStepnc / "nist_ex1.stp").project;
  tg::Options o;
  o.source_name = "nist_ex1.stp";
  const auto generated = tg::generate_toolpaths(cc2, o);
  ASSERT_TRUE(generated.cc1.rawpiece && generated.cc1.rawpiece->its_bounding_geometry);
  const setup::Stock stock = stock_of(generated.cc1);

  std::set<std::string> in, out;
  for (const auto& e : cc2.main_workplan.its_elements) {
    if (const auto* ws = std::get_if<stepnc::MachiningWorkingstep>(&e)) in.insert(ws->its_id);
  }
  for (const auto& e : generated.cc1.main_workplan.its_elements) {
    if (const auto* ws = std::get_if<stepnc::MachiningWorkingstep>(&e)) out.insert(ws->its_id);
  }
  EXPECT_EQ(in, out);
  ASSERT_FALSE(in.empty());

  mc::CheckOptions check;
  check.cell = 0.25;
  const auto designed = mc::designed_part(cc2, stock, "nist_ex1.stp");
  const auto program = mc::program_from_stepnc(generated.cc1);
  const auto report = mc::check_material(program, designed, check);
  std::printf("nist_ex1 generated: %zu features, least reached %.4f, max leftover %.3f mm, gouge %.4f mm, rapids through "
              "material %zu, plunges %zu, removed %.0f mm3\n",
              report.features.size(), report.least_reached(), report.max_leftover(), report.max_gouge,
              report.rapid_collisions, report.plunges, report.removed_volume);
  for (const auto& f : report.features) {
    std::printf("  %s: reached %.4f, leftover %.3f mm, unreachable %.1f mm2\n", f.id.c_str(), f.reached_fraction, f.max_leftover,
                f.unreachable_area);
    EXPECT_GE(f.reached_fraction, 0.999) << f.id;
  }
  EXPECT_LE(report.max_gouge, 0.01);
  EXPECT_EQ(report.rapid_collisions, 0u);
  EXPECT_EQ(report.plunges, 0u);

  // NIST's explicit toolpaths for the same features, on the same grid.
  const auto nist = step_writer::read_stepnc_file(kStepnc / "nist_ex1E.stp").project;
  const auto nist_program = mc::program_from_stepnc(nist);
  const auto nist_report = mc::check_material(nist_program, designed, check);
  const auto a = mc::simulate(nist_program, stock, check.cell);
  const auto b = mc::simulate(program, stock, check.cell);
  const auto d = mc::compare_material(a.grid, b.grid, 0.05);
  std::printf("nist_ex1E (NIST's toolpaths): least reached %.4f, gouge %.4f mm; removed %.0f (NIST) vs %.0f (generated) mm3, "
              "generated deeper by up to %.3f mm, shallower by up to %.3f mm, differing on %.0f mm2\n",
              nist_report.least_reached(), nist_report.max_gouge, a.removed_volume, b.removed_volume, d.max_deeper,
              d.max_shallower, d.differing_area);
  for (const auto& f : nist_report.features) std::printf("  NIST %s: reached %.4f\n", f.id.c_str(), f.reached_fraction);
  EXPECT_GT(b.removed_volume, 0);
}

// NIST's interpreter and the generator, from the same features and operations: the material
// check of both on the same stock finds the same features cut, each by the same tools, and
// neither cuts the part. The volumes differ where the paths do (docs/toolpaths.md).
TEST(NistEx1, GeneratedToolpathsCutTheFeaturesNistsInterpreterCutWithTheSameTools) {
  const auto cc2 = step_writer::read_stepnc_file(kStepnc / "nist_ex1.stp").project;
  tg::Options o;
  o.source_name = "nist_ex1.stp";
  const auto generated = tg::generate_toolpaths(cc2, o);
  const setup::Stock stock = stock_of(generated.cc1);
  const auto designed = mc::designed_part(cc2, stock, "nist_ex1.stp");
  mc::CheckOptions check;
  check.cell = 0.25;
  const auto ours = mc::program_from_stepnc(generated.cc1);
  const auto nist = program_from_nist_canon(kStepnc / "nist_ex1.can", cc2);
  ASSERT_EQ(nist.runs.size(), 4u);  // MILL 18MM, SPIRAL_DRILL_20MM, REAMER_22MM, MILL 18MM again

  const auto ours_report = mc::check_material(ours, designed, check);
  const auto nist_report = mc::check_material(nist, designed, check);
  const auto a = mc::simulate(nist, stock, check.cell);
  const auto b = mc::simulate(ours, stock, check.cell);
  const auto d = mc::compare_material(a.grid, b.grid, 0.05);
  std::printf("nist_ex1.can (NIST's interpreter): least reached %.4f, gouge %.4f mm, rapids through material %zu, plunges %zu; "
              "removed %.0f (NIST's .can) vs %.0f (generated) mm3, generated deeper by up to %.3f mm at (%.2f, %.2f, %.2f), "
              "shallower by up to %.3f mm at (%.2f, %.2f, %.2f), differing on %.0f mm2\n",
              nist_report.least_reached(), nist_report.max_gouge, nist_report.rapid_collisions, nist_report.plunges, a.removed_volume,
              b.removed_volume, d.max_deeper, d.max_deeper_at.x, d.max_deeper_at.y, d.max_deeper_at.z, d.max_shallower,
              d.max_shallower_at.x, d.max_shallower_at.y, d.max_shallower_at.z, d.differing_area);
  ASSERT_EQ(ours_report.features.size(), nist_report.features.size());
  for (std::size_t i = 0; i < nist_report.features.size(); ++i) {
    const auto& n = nist_report.features[i];
    const auto& g = ours_report.features[i];
    std::printf("  %s: reached %.4f (NIST's .can) / %.4f (generated), leftover %.3f / %.3f mm\n", n.id.c_str(), n.reached_fraction,
                g.reached_fraction, n.max_leftover, g.max_leftover);
    EXPECT_GE(n.reached_fraction, 0.999) << "NIST's interpreter leaves " << n.id;
    EXPECT_GE(g.reached_fraction, 0.999) << "the generator leaves " << g.id;
  }
  EXPECT_LE(nist_report.max_gouge, 0.01);
  EXPECT_LE(ours_report.max_gouge, 0.01);

  const auto nist_tools = tools_per_feature(nist, designed, check);
  const auto our_tools = tools_per_feature(ours, designed, check);
  for (const auto& f : designed.features) {
    const auto n = nist_tools.count(f.region.id) ? nist_tools.at(f.region.id) : std::set<std::string>{};
    const auto g = our_tools.count(f.region.id) ? our_tools.at(f.region.id) : std::set<std::string>{};
    std::printf("  %s cut by: %s (NIST's .can) / %s (generated)\n", f.region.id.c_str(), names(n).c_str(), names(g).c_str());
    EXPECT_FALSE(n.empty()) << f.region.id;
    EXPECT_EQ(n, g) << f.region.id;
  }
}

}  // namespace
