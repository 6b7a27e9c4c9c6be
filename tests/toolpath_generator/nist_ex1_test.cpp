// NIST's ISO 14649-11 example 1 (nist_ex1.stp: features and operations, no toolpath) given
// generated toolpaths: every workingstep gets its motion, the material check finds every feature
// cut and nothing else, and the removal is compared with NIST's own explicit-toolpath version of
// the same part (nist_ex1E.stp, what NIST's CAM made). Both read in place from the shared corpus.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>

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

}  // namespace
