// The round trip the generator exists for, over every corpus part (shared/corpus/cam, the paper's
// parts, tests/cc2/parts): program -> CC2 (recognised) -> generated toolpaths (CC1') ->
// recognised again (CC2'). Each generated program is checked by the material check against the
// features of the CC2 model, and its removal compared with the original program's on the same
// grid. The figures are printed (one line per part) and asserted.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "cc2_comparison.hpp"
#include "ncbridge/feature_recognizer/cc1_input.hpp"
#include "ncbridge/feature_recognizer/recognizer.hpp"
#include "ncbridge/feature_recognizer/to_stepnc.hpp"
#include "ncbridge/material_check/material_check.hpp"
#include "ncbridge/toolpath_generator/toolpath_generator.hpp"
#include "program_pipeline.hpp"

namespace mc = ncbridge::material_check;
namespace ts = ncbridge::test_support;
namespace tg = ncbridge::toolpath_generator;
using namespace ncbridge;

namespace {

const std::vector<std::string> kParts = {
    "face_mill",          "test_part",         "p01_block_reference", "p02_plate_center_zero",   "p03_bracket_steps",
    "p04_open_pockets",   "p05_slots",         "p06_nested_pockets",  "p07_helix_holes",         "p08_multi_level",
    "p09_small_part",     "p10_plate",         "p11_slots_rotated_pocket", "p12_freecad_style"};

// The recognition round trip is not identical on every part yet (docs/toolpaths.md, "Known
// limits"): how many differences each such part has today, at most. Every other part must come
// back with the same features and operations.
// Since the recogniser's strategy analysis learned FreeCAD's zigzag-and-contour orders
// (BIDIRECTIONAL_CONTOUR), some generated strategies read back as another one: the material
// removed is the same (checked above), the strategy named differs.
const std::map<std::string, std::size_t> kKnownDifferences = {
    // STEP1's CONTOUR_BIDIRECTIONAL is generated as one pass along the step (the recogniser reads
    // the feed direction off the contour, along the step, and the step is one cutter wide) and
    // comes back CENTER_MILLING. Hidden until 2026-11-26: the comparison printed every strategy
    // it did not name as CENTER_MILLING, so the two compared equal.
    {"p01_block_reference", 1},
    {"p03_bracket_steps", 2},  // a face's stepover side is named; a BIDIRECTIONAL_CONTOUR step comes back BIDIRECTIONAL
    {"p05_slots", 1},          // a BIDIRECTIONAL slot comes back BIDIRECTIONAL_CONTOUR
    {"p08_multi_level", 10},   // steps 0.5 mm off; profile, step and open pocket read as other features
    {"p12_freecad_style", 1},  // one open pocket 0.5 mm off
};

struct RoundTrip {
  ts::PipelineResult original;
  tg::GeneratedToolpaths generated;
  mc::MaterialReport report;           // the generated toolpaths against the CC2 features
  mc::MaterialReport original_report;  // the original program against the same features
  mc::MaterialDifference removal;      // original (a) vs generated (b)
  ts::Cc2Comparison recognised;        // CC2 vs CC2' recognised from the generated toolpaths
};

RoundTrip round_trip(const std::string& name) {
  const auto part = ts::corpus_part(name);
  RoundTrip r;
  r.original = ts::run_forward_pipeline(part.program, part.tools, part.stock);
  tg::Options o;
  o.stock = r.original.stock;
  o.source_name = name;
  r.generated = tg::generate_toolpaths(r.original.cc2, o);
  const auto designed = mc::designed_part(r.original.cc2, r.original.stock, name);
  mc::CheckOptions check;
  check.cell = 0.2;
  const auto generated_program = mc::program_from_stepnc(r.generated.cc1);
  const auto original_program = mc::program_from_stepnc(r.original.cc1);
  r.report = mc::check_material(generated_program, designed, check);
  r.original_report = mc::check_material(original_program, designed, check);
  const auto a = mc::simulate(original_program, r.original.stock, check.cell);
  const auto b = mc::simulate(generated_program, r.original.stock, check.cell);
  r.removal = mc::compare_material(a.grid, b.grid, 0.05);
  r.removal.volume_a = a.removed_volume;
  r.removal.volume_b = b.removed_volume;
  const auto features = feature_recognizer::recognize(feature_recognizer::workingsteps_from_cc1(r.generated.cc1), r.original.stock);
  const auto cc2_again = feature_recognizer::cc2_from_cc1(r.generated.cc1, features).project;
  r.recognised = ts::compare_cc2(r.original.cc2, cc2_again, r.original.stock);
  return r;
}

class CorpusRoundTrip : public testing::TestWithParam<std::string> {};

TEST_P(CorpusRoundTrip, GeneratedToolpathsCutTheFeaturesAndNothingElse) {
  const std::string name = GetParam();
  RoundTrip r;
  ASSERT_NO_THROW(r = round_trip(name));
  const auto& m = r.report;
  std::printf("%-26s generated: least reached %.4f, max leftover %.3f mm, gouge %.4f mm (%.1f mm2), rapids through material %zu, "
              "plunges %zu | original: least reached %.4f, gouge %.4f | removed %.0f vs %.0f mm3 (%+.2f%%), deeper %.3f, "
              "shallower %.3f, differing %.0f mm2 | recognised again: %d/%d features, %d/%d operations\n",
              name.c_str(), m.least_reached(), m.max_leftover(), m.max_gouge, m.gouge_area, m.rapid_collisions, m.plunges,
              r.original_report.least_reached(), r.original_report.max_gouge, r.removal.volume_a, r.removal.volume_b,
              100 * (r.removal.volume_b - r.removal.volume_a) / r.removal.volume_a, r.removal.max_deeper,
              r.removal.max_shallower, r.removal.differing_area, r.recognised.matched, r.recognised.features,
              r.recognised.operations_matched, r.recognised.operations);
  for (const auto& d : r.recognised.differences) std::printf("  %s: %s\n", name.c_str(), d.c_str());
  for (const auto& f : m.features) {
    if (f.reached_fraction < 0.999) {
      std::printf("  %s: %s reached %.4f, leftover %.3f at (%.2f, %.2f, %.2f)\n", name.c_str(), f.id.c_str(), f.reached_fraction,
                  f.max_leftover, f.max_leftover_at.x, f.max_leftover_at.y, f.max_leftover_at.z);
    }
  }
  for (const auto& f : m.findings) {
    std::printf("  %s: %s in %s from (%.2f %.2f %.2f) to (%.2f %.2f %.2f) depth %.3f\n", name.c_str(),
                f.kind == mc::Finding::Kind::Plunge ? "plunge" : "rapid through material", f.workingstep.c_str(), f.from.x,
                f.from.y, f.from.z, f.to.x, f.to.y, f.to.z, f.depth);
  }
  if (m.max_gouge > 0.01) {  // which workingstep gouges first: the shortest prefix of the program that does
    const auto program = mc::program_from_stepnc(r.generated.cc1);
    const auto designed = mc::designed_part(r.original.cc2, r.original.stock, name);
    mc::CheckOptions check;
    check.cell = 0.2;
    for (std::size_t k = 1; k <= program.runs.size(); ++k) {
      mc::ToolpathProgram prefix;
      prefix.runs.assign(program.runs.begin(), program.runs.begin() + static_cast<std::ptrdiff_t>(k));
      const auto g = mc::check_material(prefix, designed, check);
      if (g.max_gouge > 0.01) {
        std::printf("  %s: first gouge (%.3f mm) by %s\n", name.c_str(), g.max_gouge, program.runs[k - 1].workingstep.c_str());
        break;
      }
    }
  }
  // Nothing cut that the features do not remove, never a rapid through material, never a plunge
  // with a milling cutter.
  EXPECT_LE(m.max_gouge, 0.01) << "at " << m.max_gouge_at.x << " " << m.max_gouge_at.y << " " << m.max_gouge_at.z;
  EXPECT_EQ(m.rapid_collisions, 0u);
  EXPECT_EQ(m.plunges, 0u);
  // Every feature cut to its design, within the tolerance and its operations' allowances.
  for (const auto& f : m.features) EXPECT_GE(f.reached_fraction, 0.999) << f.id << ": leftover " << f.max_leftover << " mm";
  // Recognised again: the same features with the same operations and strategies.
  const auto known = kKnownDifferences.find(name);
  const std::size_t allowed = known == kKnownDifferences.end() ? 0 : known->second;
  EXPECT_LE(r.recognised.differences.size(), allowed) << "the generated toolpaths are recognised as other features or operations";
  EXPECT_GT(r.recognised.features, 0);
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusRoundTrip, testing::ValuesIn(kParts),
                         [](const testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
