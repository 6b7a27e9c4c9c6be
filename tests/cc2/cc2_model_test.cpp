// The CC2 model the mapping builds (read back from the files `ncbridge convert --level cc2`
// writes): the paper's appendix A.2 shape for face_mill.ngc, the Figure 8 test part, and the
// frames of open features on hand-made recognised features.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "ncbridge/feature_recognizer/to_stepnc.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

namespace fr = ncbridge::feature_recognizer;
namespace sn = ncbridge::stepnc;
namespace sw = ncbridge::step_writer;
namespace fs = std::filesystem;

namespace {

const fs::path kPaper = fs::path(NCBRIDGE_SHARED_DIR) / "corpus" / "paper";

sn::Project convert_paper(const std::string& program) {
  const fs::path out = fs::temp_directory_path() / ("ncbridge_cc2_model_" + program + ".stp");
  const std::string command = "'" + (fs::path(NCBRIDGE_BINARY_DIR) / "bin" / "ncbridge").string() + "' convert '" +
                              (kPaper / program).string() + "' --tools '" + (kPaper / "tools.json").string() + "' --stock '" +
                              (kPaper / "stock.json").string() + "' --level cc2 -o '" + out.string() + "' 2>/dev/null";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return sw::read_stepnc_file(out).project;
}

std::vector<const sn::MachiningWorkingstep*> workingsteps(const sn::Project& p) {
  std::vector<const sn::MachiningWorkingstep*> out;
  for (const auto& e : p.main_workplan.its_elements) {
    if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) out.push_back(ws);
  }
  return out;
}

}  // namespace

TEST(Cc2Model, FaceMillIsOnePlanarFaceFinishedBidirectionallyAlongYAsInAppendixA2) {
  const sn::Project p = convert_paper("face_mill.ngc");
  ASSERT_EQ(p.features.size(), 1u);
  const auto* face = std::get_if<sn::PlanarFace>(&p.features[0]);
  ASSERT_NE(face, nullptr);
  // Placement at the face's corner on the stock top, depth plane 5 below, course of travel 120
  // along J, removal boundary 100 (appendix A.2: #64, #66, #21, #22).
  EXPECT_EQ(face->feature_placement.location, (sn::CartesianPoint{0, 0, 5}));
  EXPECT_EQ(face->feature_placement.ref_direction, (sn::Direction{1, 0, 0}));
  EXPECT_EQ(face->depth.position.location, (sn::CartesianPoint{0, 0, -5}));
  EXPECT_DOUBLE_EQ(face->course_of_travel.distance.theoretical_size, 120);
  EXPECT_EQ(face->course_of_travel.its_direction, (sn::Direction{0, 1, 0}));
  EXPECT_DOUBLE_EQ(face->removal_boundary.profile_length, 100);

  const auto ws = workingsteps(p);
  ASSERT_EQ(ws.size(), 1u);
  const auto* op = std::get_if<sn::PlaneFinishMilling>(&p.operation(ws[0]->its_operation));
  ASSERT_NE(op, nullptr);
  ASSERT_TRUE(op->its_machining_strategy.has_value());
  const auto* bidirectional = std::get_if<sn::Bidirectional>(&*op->its_machining_strategy);
  ASSERT_NE(bidirectional, nullptr);
  EXPECT_EQ(bidirectional->feed_direction, (sn::Direction{0, 1, 0}));
  EXPECT_EQ(bidirectional->stepover_direction, sn::LeftOrRight::Left);  // passes step towards -X
  EXPECT_EQ(op->axial_cutting_depth, 5.0);
  ASSERT_TRUE(op->its_toolpath.has_value());  // the CC1 cutter locations are kept
  EXPECT_FALSE(op->its_toolpath->its_list.empty());
  EXPECT_EQ(p.tool(op->its_tool).dimension.diameter, 18);
}

TEST(Cc2Model, TestPartHasAFaceAPocketRoughedThenFinishedAndAReamedThroughHole) {
  const sn::Project p = convert_paper("test_part.ngc");
  ASSERT_EQ(p.features.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<sn::PlanarFace>(p.features[0]));
  const auto* pocket = std::get_if<sn::ClosedPocket>(&p.features[1]);
  ASSERT_NE(pocket, nullptr);
  EXPECT_EQ(pocket->feature_placement.location, (sn::CartesianPoint{70, 70, 0}));
  EXPECT_EQ(pocket->feature_placement.ref_direction, (sn::Direction{0, 1, 0}));  // the long side along Y
  const auto* rect = std::get_if<sn::RectangularClosedProfile>(&pocket->feature_boundary);
  ASSERT_NE(rect, nullptr);
  EXPECT_NEAR(rect->profile_length.theoretical_size, 80, 0.05);
  EXPECT_NEAR(rect->profile_width.theoretical_size, 50, 0.05);
  ASSERT_TRUE(pocket->orthogonal_radius.has_value());
  EXPECT_NEAR(pocket->orthogonal_radius->theoretical_size, 10, 0.2);
  const auto* hole = std::get_if<sn::RoundHole>(&p.features[2]);
  ASSERT_NE(hole, nullptr);
  EXPECT_TRUE(std::holds_alternative<sn::ThroughBottomCondition>(hole->bottom_condition));
  EXPECT_DOUBLE_EQ(hole->diameter.theoretical_size, 22);

  const auto ws = workingsteps(p);
  ASSERT_EQ(ws.size(), 5u);  // face, pocket rough, pocket finish, drill, ream (paper A.2: #10-#14)
  std::vector<std::string> kinds;
  for (const auto* w : ws) kinds.emplace_back(sn::entity_name(p.operation(w->its_operation)));
  EXPECT_EQ(kinds, (std::vector<std::string>{"PLANE_FINISH_MILLING", "BOTTOM_AND_SIDE_ROUGH_MILLING",
                                             "BOTTOM_AND_SIDE_FINISH_MILLING", "DRILLING", "REAMING"}));
  const auto& rough = std::get<sn::BottomAndSideRoughMilling>(p.operation(ws[1]->its_operation));
  EXPECT_NEAR(rough.allowance_bottom.value_or(-1), 0.5, 1e-6);
  EXPECT_NEAR(rough.allowance_side.value_or(-1), 1.0, 0.05);
  EXPECT_NEAR(rough.axial_cutting_depth.value_or(-1), 5.9, 1e-6);
  const auto& drill = std::get<sn::Drilling>(p.operation(ws[3]->its_operation));
  EXPECT_NEAR(drill.cutting_depth.value_or(-1), 60, 1e-6);  // G81 to Z-60 from the hole's top at Z0
  ASSERT_TRUE(drill.its_toolpath.has_value());              // three G81 depths, kept as explicit passes
  EXPECT_EQ(drill.its_toolpath->its_list.size(), 3u);
  for (const auto* w : {ws[3], ws[4]}) EXPECT_EQ(w->its_feature.index, 2u);
}

TEST(Cc2Model, OpenPocketBoundaryIsSplitIntoTheOpenSideAndTheWalls) {
  fr::RecognizedFeature f;
  f.type = fr::FeatureType::OpenPocket;
  f.x = 45, f.y = 12.5, f.top_z = 0, f.bottom_z = -10;
  f.profile.outline = {{30, 0}, {60, 0}, {60, 25}, {30, 25}};
  f.profile.length = 30, f.profile.width = 25;
  f.open_sides = {fr::OpenSide::YMinus};
  const auto cc2 = fr::cc2_from_cc1(sn::Project{}, {f});
  ASSERT_EQ(cc2.project.features.size(), 1u);
  const auto& pocket = std::get<sn::OpenPocket>(cc2.project.features[0]);
  EXPECT_EQ(pocket.feature_placement.location, (sn::CartesianPoint{45, 12.5, 0}));
  const auto& open = std::get<sn::GeneralProfile>(pocket.open_boundary);
  const auto& open_points = std::get<sn::Polyline>(open.its_profile.segments.at(0)).points;
  ASSERT_EQ(open_points.size(), 2u);  // the edge on y = 0, in the pocket's frame
  EXPECT_EQ(open_points[0], (sn::CartesianPoint{-15, -12.5, 0}));
  EXPECT_EQ(open_points[1], (sn::CartesianPoint{15, -12.5, 0}));
  ASSERT_TRUE(pocket.wall_boundary.has_value());
  EXPECT_EQ(std::get<sn::Polyline>(std::get<sn::GeneralProfile>(*pocket.wall_boundary).its_profile.segments.at(0)).points.size(), 4u);
  EXPECT_EQ(cc2.feature_ids, std::vector<std::string>{"OPEN POCKET1"});
}

TEST(Cc2Model, StepFrameStartsAtItsWallWithYTowardsTheOpenSide) {
  fr::RecognizedFeature f;
  f.type = fr::FeatureType::Step;
  f.x = 95, f.y = 40, f.top_z = 30, f.bottom_z = 22;
  f.profile.outline = {{90, 0}, {100, 0}, {100, 80}, {90, 80}};
  f.open_sides = {fr::OpenSide::XPlus, fr::OpenSide::YMinus, fr::OpenSide::YPlus};
  const auto cc2 = fr::cc2_from_cc1(sn::Project{}, {f});
  const auto& step = std::get<sn::Step>(cc2.project.features.at(0));
  // Open along x = 100, its wall at x = 90: local x runs along the wall (-Y), local y out of
  // the part (+X), towards the open side.
  EXPECT_EQ(step.feature_placement.location, (sn::CartesianPoint{90, 80, 30}));
  EXPECT_EQ(step.feature_placement.ref_direction, (sn::Direction{0, -1, 0}));
  EXPECT_DOUBLE_EQ(step.open_boundary.distance.theoretical_size, 80);
  EXPECT_EQ(step.depth.position.location, (sn::CartesianPoint{0, 0, -8}));
}
