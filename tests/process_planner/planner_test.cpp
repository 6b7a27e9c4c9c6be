// The planning rules (docs/plan.md) on our AP224 files and on hand-made parts: which operations,
// which tools, in which order, with which depths and cutting data; every plan is a CC2 model the
// ISO 14649 schema accepts and that reads back unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <variant>

#include "ncbridge/common/error.hpp"
#include "ncbridge/part_reader/ap224_reader.hpp"
#include "ncbridge/process_planner/planner.hpp"
#include "ncbridge/step_writer/express_schema.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/schema_check.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

namespace pp = ncbridge::process_planner;
namespace pr = ncbridge::part_reader;
namespace sn = ncbridge::stepnc;
namespace sw = ncbridge::step_writer;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = NCBRIDGE_SOURCE_DIR;
const fs::path kShared = NCBRIDGE_SHARED_DIR;
const fs::path kParts = kSource / "tests" / "part_reader" / "data";
const fs::path kTools = kSource / "tests" / "process_planner" / "data";

ncbridge::setup::ToolList shop_tools() { return ncbridge::setup::read_tool_list(kTools / "shop_tools.json"); }

ncbridge::setup::Stock stock_of(const pr::Part& part) {
  const pr::Box b = pr::bounding_box(*part.stock);
  return {b.min, b.max};
}

pp::Plan plan_file(const fs::path& file, const ncbridge::setup::ToolList& tools, pr::SetupUp up = pr::SetupUp::PlusZ) {
  const pr::Part part = pr::read_ap224_file(file, {up, {0, 0, 0}});
  return pp::plan(part, stock_of(part), tools);
}

// The workplan as "operation id (entity, tool number)".
struct Step {
  std::string id, entity;
  int tool = 0;
  const sn::Operation* op = nullptr;
  const sn::Feature* feature = nullptr;
};

std::vector<Step> steps(const pp::Plan& plan) {
  std::vector<Step> out;
  for (const auto& e : plan.project.main_workplan.its_elements) {
    const auto& ws = std::get<sn::MachiningWorkingstep>(e);
    const auto& op = plan.project.operation(ws.its_operation);
    const auto& mop = sn::machining_operation(op);
    out.push_back({mop.its_id, std::string(sn::entity_name(op)), plan.project.tool(mop.its_tool).number, &op,
                   &plan.project.feature(ws.its_feature)});
  }
  return out;
}

const Step& step_named(const std::vector<Step>& all, const std::string& id) {
  for (const auto& s : all) {
    if (s.id == id) return s;
  }
  throw std::runtime_error("no operation " + id);
}

const sw::express::Schema& schema() {
  static const auto s = sw::express::Schema::parse_file(kShared / "reference" / "iso14649" / "combined_schema_iso14649_only.exp");
  return s;
}

// Schema-valid, and written -> read -> written gives the same bytes.
void expect_valid_cc2(const pp::Plan& plan) {
  sw::StepncWriteOptions options;
  options.file_name = "plan.stp";
  options.unix_time = 1700000000;
  options.description = {"ISO 14649 CC2 program written by ncbridge"};
  const std::string text = sw::write_stepnc(plan.project, options);
  const auto graph = sw::part21::read_part21(text, "plan.stp");
  const auto diagnostics = sw::check_instances(graph.graph, schema());
  for (const auto& d : diagnostics) ADD_FAILURE() << d.to_string();
  const auto back = sw::read_stepnc(text, "plan.stp");
  EXPECT_TRUE(back.warnings.empty());
  EXPECT_EQ(sw::write_stepnc(back.project, options), text);
}

pr::Feature hole(double x, double y, double top, double diameter, double depth, pr::HoleBottom bottom) {
  pr::Feature f;
  f.kind = pr::FeatureKind::RoundHole;
  f.source = "test";
  f.placement.location = {x, y, top};
  f.diameter = diameter;
  f.depth = depth;
  f.bottom = bottom;
  f.outline = pr::Outline::Circle;
  return f;
}

pr::Part block_with(std::vector<pr::Feature> features) {
  pr::Part part;
  part.name = "TEST_BLOCK";
  part.file = "test.stp";
  part.features = std::move(features);
  part.bounds = pr::Box{{0, 0, 0}, {100, 100, 50}};
  return part;
}

const ncbridge::setup::Stock kBlock{{0, 0, 0}, {100, 100, 50}};

template <class T>
const T& as(const Step& s) {
  const T* t = std::get_if<T>(s.op);
  if (!t) throw std::runtime_error(s.id + " is a " + s.entity);
  return *t;
}

}  // namespace

TEST(PlannerPaperBlock, SlotWithACutterOfItsWidthHoleMilledHelically) {
  const pp::Plan plan = plan_file(kParts / "paper_block_ap224.stp", shop_tools());
  ASSERT_EQ(plan.project.features.size(), 2u);
  EXPECT_EQ(sn::feature_id(plan.project.features[0]), "HOLE1 D=75MM");
  EXPECT_EQ(sn::feature_id(plan.project.features[1]), "SLOT1");
  const auto all = steps(plan);
  ASSERT_EQ(all.size(), 3u);
  // The slot, with the 25 mm end mill down its centre line (roughing phase, before the holes).
  EXPECT_EQ(all[0].id, "MILL SLOT1");
  EXPECT_EQ(all[0].tool, 2);
  const auto& slot = as<sn::BottomAndSideFinishMilling>(all[0]);
  ASSERT_TRUE(slot.its_machining_strategy.has_value());
  EXPECT_TRUE(std::holds_alternative<sn::CenterMilling>(*slot.its_machining_strategy));
  EXPECT_DOUBLE_EQ(*slot.axial_cutting_depth, 12.5);  // half the cutter's diameter
  // No drill of 75 mm: helical milling with the largest end mill that fits.
  EXPECT_EQ(all[1].id, "ROUGH HOLE1 D=75MM");
  EXPECT_EQ(all[1].tool, 2);
  const auto& rough = as<sn::BottomAndSideRoughMilling>(all[1]);
  EXPECT_TRUE(std::holds_alternative<sn::ContourSpiral>(*rough.its_machining_strategy));
  EXPECT_DOUBLE_EQ(*rough.allowance_bottom, 0);  // a through hole has no floor
  EXPECT_EQ(all[2].id, "FINISH HOLE1 D=75MM");
  const auto& slot_feature = std::get<sn::Slot>(plan.project.features[1]);
  EXPECT_EQ(slot_feature.feature_placement.location, (sn::CartesianPoint{225, 50, 12.5}));
  EXPECT_EQ(slot_feature.feature_placement.ref_direction, (sn::Direction{-1, 0, 0}));
  EXPECT_DOUBLE_EQ(slot_feature.course_of_travel.distance.theoretical_size, 75);
  EXPECT_EQ(slot_feature.end_conditions, (std::vector<sn::SlotEndType>{sn::SlotEndType::Open, sn::SlotEndType::Radiused}));
  ASSERT_TRUE(plan.project.rawpiece.has_value());
  EXPECT_DOUBLE_EQ(plan.project.rawpiece->its_bounding_geometry->x, 225);
  EXPECT_DOUBLE_EQ(plan.project.setup.its_secplane.position.location.z, 22.5);
  expect_valid_cc2(plan);
}

TEST(PlannerMilledPlate, FacesThenRoughingThenHolesThenFinishing) {
  const pp::Plan plan = plan_file(kParts / "milled_plate_ap224.stp", shop_tools());
  const auto all = steps(plan);
  std::vector<std::string> ids;
  for (const auto& s : all) ids.push_back(s.id);
  const std::vector<std::string> expected = {
      "ROUGH PLANAR FACE1", "FINISH PLANAR FACE1",
      // roughing, by tool: D25 (step), D16 (cutout), D10 (pocket), D6 (open pocket)
      "ROUGH STEP1", "ROUGH POCKET2", "ROUGH POCKET1", "ROUGH OPEN POCKET1",
      // holes: the counterbore milled first, then centre drilling, then drilling by tool
      "ROUGH HOLE1 D=12.7MM", "FINISH HOLE1 D=12.7MM", "CENTER DRILL HOLE2 D=7.938MM", "CENTER DRILL HOLE3 D=6.35MM",
      "DRILL HOLE3 D=6.35MM", "PECK DRILL HOLE2 D=7.938MM",  // 33.9 mm deep: more than 3 diameters
      // finishing, by tool
      "FINISH STEP1", "FINISH POCKET2", "FINISH POCKET1", "FINISH OPEN POCKET1"};
  EXPECT_EQ(ids, expected);
  EXPECT_EQ(step_named(all, "ROUGH PLANAR FACE1").tool, 1);
  EXPECT_EQ(step_named(all, "ROUGH POCKET1").tool, 4);       // D10: its corners are 6.35 mm
  EXPECT_EQ(step_named(all, "ROUGH POCKET2").tool, 3);       // the 25.4 mm cutout: D16
  EXPECT_EQ(step_named(all, "ROUGH OPEN POCKET1").tool, 5);  // corners of 3.175 mm: D6
  EXPECT_EQ(step_named(all, "ROUGH HOLE1 D=12.7MM").tool, 4);  // the counterbore, milled with D10
  EXPECT_EQ(step_named(all, "PECK DRILL HOLE2 D=7.938MM").tool, 12);
  EXPECT_EQ(step_named(all, "CENTER DRILL HOLE2 D=7.938MM").tool, 10);

  // The through hole below the counterbore: the full diameter comes out 1 mm below the part.
  const auto& through = as<sn::MultistepDrilling>(step_named(all, "PECK DRILL HOLE2 D=7.938MM"));
  const double tip = 7.9375 / 2 / std::tan(59 * M_PI / 180);
  EXPECT_NEAR(*through.cutting_depth, 1.2 * 25.4 + tip + 1, 1e-6);
  EXPECT_DOUBLE_EQ(*through.retract_plane, 2);
  // The 118 degree conical bottom is the drill's own point: drilled to the hole's depth.
  EXPECT_NEAR(*as<sn::Drilling>(step_named(all, "DRILL HOLE3 D=6.35MM")).cutting_depth, 0.6 * 25.4, 1e-6);
  // Facing 1.27 mm: a roughing pass leaving 0.2 and a finishing pass.
  const auto& face_rough = as<sn::PlaneRoughMilling>(step_named(all, "ROUGH PLANAR FACE1"));
  EXPECT_NEAR(*face_rough.axial_cutting_depth, 1.07, 1e-9);
  EXPECT_NEAR(*face_rough.allowance_bottom, 0.2, 1e-9);
  const auto& pocket_rough = as<sn::BottomAndSideRoughMilling>(step_named(all, "ROUGH POCKET1"));
  EXPECT_DOUBLE_EQ(*pocket_rough.axial_cutting_depth, 5);  // half the cutter
  EXPECT_DOUBLE_EQ(*pocket_rough.allowance_side, 0.5);
  EXPECT_DOUBLE_EQ(*pocket_rough.allowance_bottom, 0.2);
  EXPECT_DOUBLE_EQ(*as<sn::BottomAndSideFinishMilling>(step_named(all, "FINISH POCKET1")).axial_cutting_depth, 12.7);
  expect_valid_cc2(plan);
}

TEST(PlannerMilledPlate, CuttingDataDefaultsForTheMaterial) {
  const pp::Plan plan = plan_file(kParts / "milled_plate_ap224.stp", shop_tools());
  const auto all = steps(plan);
  const auto& pocket = sn::machining_operation(*step_named(all, "ROUGH POCKET1").op);
  const auto& tech = plan.project.technology(pocket.its_technology);
  // Steel, D10 with 3 teeth: 120 m/min -> 3820 rev/min; 0.04 mm per tooth -> 458 mm/min.
  EXPECT_NEAR(*tech.spindle, -3820.0 / 60, 1e-6);
  EXPECT_NEAR(*tech.feedrate, 458.0 / 60000, 1e-9);
  const auto& drill = sn::machining_operation(*step_named(all, "DRILL HOLE3 D=6.35MM").op);
  const auto& drill_tech = plan.project.technology(drill.its_technology);
  // 70 m/min on 6.35 mm -> 3509 rev/min; 0.15 mm/rev * 0.635 -> 334 mm/min.
  EXPECT_NEAR(*drill_tech.spindle, -3509.0 / 60, 1e-6);
  EXPECT_NEAR(*drill_tech.feedrate, 334.0 / 60000, 1e-9);
}

TEST(PlannerCuttingData, TheToolListsValuesWin) {
  pr::Part part = block_with({hole(50, 50, 50, 10, 20, pr::HoleBottom::Flat)});
  const auto tools = ncbridge::setup::read_tool_list(kShared / "corpus" / "cam" / "p01_block_reference" / "tools.json");
  const pp::Plan plan = pp::plan(part, kBlock, tools);
  const auto all = steps(plan);
  const auto& drill = sn::machining_operation(*step_named(all, "DRILL HOLE1 D=10MM").op);
  EXPECT_EQ(all[0].tool, 4);
  const auto& tech = plan.project.technology(drill.its_technology);
  EXPECT_NEAR(*tech.spindle, -1500.0 / 60, 1e-9);  // rpm 1500, feed 150 in the tool list
  EXPECT_NEAR(*tech.feedrate, 150.0 / 60000, 1e-9);
  // Flat bottom: the D10 end mill flattens what the drill's point left.
  EXPECT_EQ(step_named(all, "FINISH HOLE1 D=10MM").tool, 2);
}

TEST(PlannerHoles, DeepHolesArePeckDrilled) {
  const pp::Plan plan = pp::plan(block_with({hole(50, 50, 50, 8, 40, pr::HoleBottom::Conical)}), kBlock, shop_tools());
  const auto all = steps(plan);
  const auto& peck = as<sn::MultistepDrilling>(step_named(all, "PECK DRILL HOLE1 D=8MM"));
  EXPECT_EQ(step_named(all, "PECK DRILL HOLE1 D=8MM").tool, 13);
  EXPECT_DOUBLE_EQ(peck.first_depth, 8);
  EXPECT_DOUBLE_EQ(peck.depth_of_step, 8);
  EXPECT_DOUBLE_EQ(*peck.cutting_depth, 40);
  expect_valid_cc2(plan);
}

TEST(PlannerHoles, ReamedWhereTheToleranceAsks) {
  pr::Feature h = hole(50, 50, 50, 8, 20, pr::HoleBottom::Through);
  h.diameter_tolerance = std::make_pair(0.015, 0.0);
  const pp::Plan plan = pp::plan(block_with({h}), kBlock, shop_tools());
  const auto all = steps(plan);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].id, "CENTER DRILL HOLE1 D=8MM");
  EXPECT_EQ(all[1].id, "DRILL HOLE1 D=8MM");
  EXPECT_EQ(all[1].tool, 14);  // 7.8 mm: 0.2 under size
  EXPECT_EQ(all[2].id, "REAM HOLE1 D=8MM");
  EXPECT_EQ(all[2].tool, 15);
  EXPECT_DOUBLE_EQ(*as<sn::Reaming>(all[2]).previous_diameter, 7.8);
  const auto& feature = std::get<sn::RoundHole>(plan.project.features[0]);
  EXPECT_DOUBLE_EQ(feature.diameter.upper_limit, 0.015);
  EXPECT_DOUBLE_EQ(feature.diameter.lower_limit, 0);
  expect_valid_cc2(plan);

  // The same hole without a reamer in the list: drilled, and said.
  auto tools = shop_tools().tools();
  std::erase_if(tools, [](const auto& t) { return t.type == ncbridge::setup::ToolType::Reamer; });
  const pp::Plan drilled = pp::plan(block_with({h}), kBlock, ncbridge::setup::ToolList(tools));
  EXPECT_EQ(steps(drilled)[1].tool, 13);
  ASSERT_EQ(drilled.warnings.size(), 1u);
  EXPECT_NE(drilled.warnings[0].message.find("asks for reaming"), std::string::npos) << drilled.warnings[0].message;
}

TEST(PlannerHoles, FlatBottomWithoutAnEndMillIsSaid) {
  auto tools = shop_tools().tools();
  std::erase_if(tools, [](const auto& t) { return t.type == ncbridge::setup::ToolType::FlatEndMill && t.diameter <= 8; });
  const pp::Plan plan = pp::plan(block_with({hole(50, 50, 50, 8, 10, pr::HoleBottom::Flat)}), kBlock, ncbridge::setup::ToolList(tools));
  ASSERT_EQ(steps(plan).size(), 2u);
  ASSERT_EQ(plan.warnings.size(), 1u);
  EXPECT_NE(plan.warnings[0].message.find("the drill's point is left"), std::string::npos);
}

TEST(PlannerBadInput, AFeatureNoToolCanMakeIsAnErrorNamingIt) {
  const pr::Part part = pr::read_ap224_file(kParts / "milled_plate_ap224.stp");
  const auto tools = ncbridge::setup::read_tool_list(kTools / "end_mills_d25_only.json");
  try {
    pp::plan(part, stock_of(part), tools);
    FAIL() << "planned without a small end mill";
  } catch (const ncbridge::InputError& e) {
    EXPECT_EQ(e.message(), "POCKET1 (#71): needs a flat end mill of at most 12.7 mm (corner radius 6.35 mm) with flutes reaching 12.7 mm");
    EXPECT_EQ(e.where().line, 78u);  // the pocket's instance
  }
  try {
    pp::plan(block_with({hole(50, 50, 50, 7.3, 10, pr::HoleBottom::Through)}), kBlock, ncbridge::setup::ToolList());
    FAIL() << "planned a hole without tools";
  } catch (const ncbridge::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("HOLE1 D=7.3MM (test): needs a drill of 7.3 mm"), std::string::npos) << e.what();
  }
}

TEST(PlannerBadInput, AnOutlineWithSharpInsideCornersAsksForAnyDiameterThatReaches) {
  // An L-shaped part 100 mm tall: its inside corner is sharp, any end mill leaves it rounded; none
  // of the shop's reaches 100 mm.
  pr::Feature profile;
  profile.kind = pr::FeatureKind::GeneralOutsideProfile;
  profile.source = "test";
  profile.placement.location = {0, 0, 100};
  profile.depth = 100;
  profile.outline = pr::Outline::General;
  profile.boundary = {{0, 0}, {100, 0}, {100, 40}, {40, 40}, {40, 100}, {0, 100}};
  pr::Part part = block_with({profile});
  part.bounds = pr::Box{{0, 0, 0}, {100, 100, 100}};
  try {
    pp::plan(part, {{0, 0, 0}, {100, 100, 100}}, shop_tools());
    FAIL() << "planned a 100 mm wall with 40 mm flutes";
  } catch (const ncbridge::InputError& e) {
    EXPECT_EQ(e.message(), "PROFILE1 (test): needs a flat end mill with flutes reaching 100 mm");
  }
  profile.depth = 30;
  profile.placement.location.z = 30;
  part = block_with({profile});
  part.bounds = pr::Box{{0, 0, 0}, {100, 100, 30}};
  const pp::Plan plan = pp::plan(part, {{0, 0, 0}, {100, 100, 30}}, shop_tools());
  ASSERT_EQ(plan.warnings.size(), 1u);
  EXPECT_NE(plan.warnings[0].message.find("sharp inside corners of the outline"), std::string::npos) << plan.warnings[0].message;
  expect_valid_cc2(plan);
}

TEST(PlannerRamp, TheCounterboreFromBelow) {
  // The RAMP part held with its -z end up: the counterbore faces the spindle.
  const pp::Plan plan = plan_file(kShared / "corpus" / "ap224" / "ramp_ap224_995277945.stp", shop_tools(), pr::SetupUp::MinusZ);
  const auto all = steps(plan);
  std::vector<std::string> ids;
  for (const auto& s : all) ids.push_back(s.id);
  // HOLE1 is the small hole (19.558: no drill, helical), HOLE2 the counterbore (28.346, milled first).
  EXPECT_EQ(ids, (std::vector<std::string>{"ROUGH HOLE2 D=28.346MM", "FINISH HOLE2 D=28.346MM", "ROUGH HOLE1 D=19.558MM",
                                           "FINISH HOLE1 D=19.558MM"}));
  EXPECT_EQ(all[0].tool, 2);  // D25 fits 28.346 - 1
  EXPECT_EQ(all[2].tool, 3);  // D16 fits 19.558 - 1
  const auto& counterbore = std::get<sn::RoundHole>(*all[0].feature);
  EXPECT_NEAR(counterbore.diameter.upper_limit, 0.0254, 1e-9);  // the file's +/- 0.001 in
  expect_valid_cc2(plan);
  // Held the default way, nothing of the part faces the spindle: an empty but valid plan.
  const pp::Plan upright = plan_file(kShared / "corpus" / "ap224" / "ramp_ap224_995277945.stp", shop_tools());
  EXPECT_TRUE(upright.project.main_workplan.its_elements.empty());
  expect_valid_cc2(upright);
}

TEST(PlannerHoles, ACountersinkIsSunkAfterItsHoleIsDrilled) {
  pr::Feature cone = hole(50, 50, 50, 12, 3, pr::HoleBottom::Conical);
  cone.tip_angle = 90;
  pr::Feature through = hole(50, 50, 47, 6.35, 47, pr::HoleBottom::Through);
  cone.compound = through.compound = 0;
  pr::Part part = block_with({cone, through});
  part.compounds.push_back({pr::CompoundKind::Countersink, "test", {0, 1}});
  auto tools = shop_tools().tools();
  EXPECT_THROW(pp::plan(part, kBlock, ncbridge::setup::ToolList(tools)), ncbridge::InputError);  // the spot drill is too small
  ncbridge::setup::Tool chamfer;
  chamfer.number = 20, chamfer.name = "CHAMFER_90", chamfer.type = ncbridge::setup::ToolType::ChamferMill, chamfer.diameter = 16,
  chamfer.point_angle = 90;
  tools.push_back(chamfer);
  const pp::Plan plan = pp::plan(part, kBlock, ncbridge::setup::ToolList(tools));
  const auto all = steps(plan);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].id, "CENTER DRILL HOLE2 D=6.35MM");
  EXPECT_EQ(all[1].id, "PECK DRILL HOLE2 D=6.35MM");
  EXPECT_EQ(all[2].id, "COUNTERSINK HOLE1 D=12MM");
  EXPECT_EQ(all[2].tool, 20);
  EXPECT_DOUBLE_EQ(*as<sn::Drilling>(all[2]).cutting_depth, 3);
  expect_valid_cc2(plan);
}
