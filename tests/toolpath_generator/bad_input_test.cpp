// Bad CC2 input: each refused with an InputError naming the workingstep and what is wrong,
// never a silent skip. The models are NIST's example 1 (read in place) with one thing broken.
#include <gtest/gtest.h>

#include <functional>

#include "ncbridge/common/error.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/toolpath_generator/toolpath_generator.hpp"

namespace fs = std::filesystem;
namespace sn = ncbridge::stepnc;
namespace tg = ncbridge::toolpath_generator;
using namespace ncbridge;

namespace {

sn::Project nist_ex1() {
  return step_writer::read_stepnc_file(fs::path(NCBRIDGE_SHARED_DIR) / "corpus/stepnc/nist_ex1.stp").project;
}

// The first workingstep whose feature is a `F`, and its operation.
template <class F>
std::pair<const sn::MachiningWorkingstep*, F*> first_with(sn::Project& p) {
  for (const auto& e : p.main_workplan.its_elements) {
    if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) {
      if (auto* f = std::get_if<F>(&p.features[ws->its_feature.index])) return {ws, f};
    }
  }
  return {nullptr, nullptr};
}

std::string refusal(const sn::Project& p) {
  tg::Options o;
  o.source_name = "broken.stp";
  try {
    tg::generate_toolpaths(p, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BadInput, ThePocketFeatureUnbrokenIsAccepted) {
  EXPECT_EQ(refusal(nist_ex1()), "");
}

TEST(BadInput, APocketWithoutSizeIsRefusedNamingItsWorkingstep) {
  auto p = nist_ex1();
  auto [ws, pocket] = first_with<sn::ClosedPocket>(p);
  ASSERT_NE(pocket, nullptr);
  auto& rect = std::get<sn::RectangularClosedProfile>(pocket->feature_boundary);
  rect.profile_width.theoretical_size = 0;
  rect.profile_length.theoretical_size = 0;
  const std::string e = refusal(p);
  EXPECT_NE(e.find("broken.stp"), std::string::npos) << e;
  EXPECT_NE(e.find(ws->its_id), std::string::npos) << e;
}

TEST(BadInput, AToolLargerThanThePocketIsRefused) {
  auto p = nist_ex1();
  auto [ws, pocket] = first_with<sn::ClosedPocket>(p);
  ASSERT_NE(pocket, nullptr);
  const auto& op = sn::machining_operation(p.operations[ws->its_operation.index]);
  p.tools[op.its_tool.index].dimension.diameter = 500;
  const std::string e = refusal(p);
  EXPECT_NE(e.find(ws->its_id), std::string::npos) << e;
}

TEST(BadInput, AHoleSmallerThanItsDrillIsRefused) {
  auto p = nist_ex1();
  auto [ws, hole] = first_with<sn::RoundHole>(p);
  ASSERT_NE(hole, nullptr);
  hole->diameter.theoretical_size = 1;
  const std::string e = refusal(p);
  EXPECT_NE(e.find(ws->its_id), std::string::npos) << e;
}

TEST(BadInput, NonsenseStrategyParametersAreRefused) {
  auto p = nist_ex1();
  auto [ws, pocket] = first_with<sn::ClosedPocket>(p);
  ASSERT_NE(pocket, nullptr);
  std::visit(
      [](auto& op) {
        if constexpr (std::is_base_of_v<sn::Two5DMillingOperation, std::decay_t<decltype(op)>>) {
          op.its_machining_strategy = sn::ContourParallel{std::nullopt, std::nullopt, 1.5, std::nullopt};  // overlap > 1
          op.radial_cutting_depth.reset();
        }
      },
      p.operations[ws->its_operation.index]);
  const std::string e = refusal(p);
  EXPECT_NE(e.find(ws->its_id), std::string::npos) << e;
}

TEST(BadInput, ADanglingOperationReferenceIsRefused) {
  auto p = nist_ex1();
  for (auto& e : p.main_workplan.its_elements) {
    if (auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) {
      ws->its_operation.index = 999;
      break;
    }
  }
  const std::string e = refusal(p);
  EXPECT_NE(e.find("operation is missing"), std::string::npos) << e;
}

TEST(BadInput, AWorkingstepOfMillionsOfPassesIsRefusedNotGenerated) {
  // 0.001 mm deep layers with a 0.001 mm stepover: about 10^10 passes; refused before any is made.
  auto p = nist_ex1();
  auto [ws, pocket] = first_with<sn::ClosedPocket>(p);
  ASSERT_NE(pocket, nullptr);
  std::visit(
      [](auto& op) {
        if constexpr (std::is_base_of_v<sn::Two5DMillingOperation, std::decay_t<decltype(op)>>) {
          op.its_machining_strategy.reset();
          op.axial_cutting_depth = 0.001;
          op.radial_cutting_depth = 0.001;
        }
      },
      p.operations[ws->its_operation.index]);
  const std::string e = refusal(p);
  EXPECT_NE(e.find(ws->its_id), std::string::npos) << e;
  EXPECT_NE(e.find("more than the generator's bound"), std::string::npos) << e;
}

}  // namespace
