// The ISO 14649 writer's layout: the setup's security plane written last under an id taken
// early, other security planes written where first used, and long lists (a workplan of many
// elements) handed on in bounded pieces; the streamed writer matches the whole-project writer.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/step_writer/stepnc_stream_writer.hpp"

namespace ncbridge::step_writer {
namespace {

namespace sn = stepnc;

sn::Plane plane_at(double z) {
  sn::Plane p;
  p.position.location.z = z;
  return p;
}

// A project of `n` rapid movements (each a two-point CONNECT polyline) under one security plane.
sn::Project rapids(std::size_t n, double secplane_z) {
  sn::Project p;
  p.its_id = "RAPIDS";
  p.workpiece.its_id = "PART";
  p.setup.its_secplane = plane_at(secplane_z);
  for (std::size_t i = 0; i < n; ++i) {
    sn::RapidMovement r;
    r.its_id = "RAPID" + std::to_string(i + 1);
    r.its_secplane = p.setup.its_secplane;
    sn::CutterLocationTrajectory t;
    t.its_type = sn::ToolpathType::Connect;
    t.basiccurve.segments.emplace_back(sn::Polyline{{{0, 0, 5}, {static_cast<double>(i % 97), 1, 5}}});
    r.its_toolpath = sn::ToolpathList{{t}};
    p.main_workplan.its_elements.emplace_back(std::move(r));
  }
  return p;
}

StepncWriteOptions options() {
  StepncWriteOptions o;
  o.file_name = "rapids.stp";
  o.unix_time = 1700000000;
  return o;
}

TEST(StepncLayout, TheSetupSecurityPlaneIsWrittenWithTheSetupUnderAnEarlyId) {
  const std::string text = write_stepnc(rapids(3, 50), options());
  const auto graph = part21::read_part21(text, "rapids.stp").graph;
  const auto planes = graph.ids_of("PLANE");
  ASSERT_EQ(planes.size(), 1u);
  const auto setups = graph.ids_of("SETUP");
  ASSERT_EQ(setups.size(), 1u);
  EXPECT_EQ(graph.at(setups[0]).attributes()[2].as_reference(), planes[0]);
  for (const auto id : graph.ids_of("RAPID_MOVEMENT")) {
    EXPECT_EQ(graph.at(id).attributes()[1].as_reference(), planes[0]);
    EXPECT_LT(planes[0], id);  // taken before the elements that name it
  }
  // ... and written after them, just before the SETUP.
  const std::size_t plane_at_text = text.find("#" + std::to_string(planes[0]) + "=PLANE(");
  ASSERT_NE(plane_at_text, std::string::npos);
  EXPECT_GT(plane_at_text, text.rfind("=RAPID_MOVEMENT("));
  EXPECT_LT(plane_at_text, text.find("=SETUP("));
  EXPECT_TRUE(write_stepnc(read_stepnc(text, "rapids.stp").project, options()) == text);
}

TEST(StepncLayout, AnotherSecurityPlaneIsItsOwnInstanceWrittenBeforeItsElement) {
  sn::Project p = rapids(2, 50);
  std::get<sn::RapidMovement>(p.main_workplan.its_elements[1]).its_secplane = plane_at(80);
  const std::string text = write_stepnc(p, options());
  const auto graph = part21::read_part21(text, "rapids.stp").graph;
  const auto moves = graph.ids_of("RAPID_MOVEMENT");
  ASSERT_EQ(moves.size(), 2u);
  const auto first = graph.at(moves[0]).attributes()[1].as_reference();
  const auto second = graph.at(moves[1]).attributes()[1].as_reference();
  EXPECT_NE(first, second);
  EXPECT_LT(second, moves[1]);
  EXPECT_LT(text.find("#" + std::to_string(second) + "=PLANE("), text.find("#" + std::to_string(moves[1]) + "="));
  const auto back = read_stepnc(text, "rapids.stp").project;
  EXPECT_EQ(std::get<sn::RapidMovement>(back.main_workplan.its_elements[1]).its_secplane, plane_at(80));
  EXPECT_TRUE(write_stepnc(back, options()) == text);
}

TEST(StepncLayout, AWorkplanLongerThanAChunkIsHandedOnInBoundedPieces) {
  const sn::Project p = rapids(200000, 50);  // the WORKPLAN instance alone is about 1.8 MB
  std::string text;
  std::size_t largest = 0;
  const std::uint64_t bytes = write_stepnc(p, options(), [&](std::string_view chunk) {
    largest = std::max(largest, chunk.size());
    text += chunk;
  });
  EXPECT_EQ(bytes, text.size());
  EXPECT_LE(largest, std::size_t{3} << 19);  // about a MB: the list did not wait for its end
  const std::size_t workplan = text.find("=WORKPLAN(");
  ASSERT_NE(workplan, std::string::npos);
  EXPECT_GT(text.find(";", workplan) - workplan, std::size_t{1} << 20);
  // Lines wrap as everywhere else, also across the pieces.
  std::size_t longest = 0, start = 0;
  for (std::size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1) longest = std::max(longest, nl - start);
  EXPECT_LE(longest, 140u);
  const auto graph = part21::read_part21(text, "rapids.stp").graph;
  EXPECT_EQ(graph.at(graph.ids_of("WORKPLAN").at(0)).attributes()[1].as_list().size(), 200000u);
}

TEST(StepncLayout, AReferenceOutsideItsTableThrowsBeforeAnythingIsAllocatedForIt) {
  sn::Project p = rapids(1, 50);
  p.tools.push_back({});
  p.technologies.push_back({});
  p.machine_functions.push_back({});
  p.features.emplace_back(sn::ToolpathFeature{});
  sn::FreeformOperation op;
  op.its_tool = sn::ToolRef{4000000000u};  // as a corrupt decoded message could hold
  p.operations.emplace_back(op);
  sn::MachiningWorkingstep ws;
  ws.its_secplane = p.setup.its_secplane;
  p.main_workplan.its_elements.emplace_back(ws);
  EXPECT_THROW(write_stepnc(p, options()), std::out_of_range);
  std::get<sn::FreeformOperation>(p.operations[0]).its_tool = sn::ToolRef{0};
  std::get<sn::MachiningWorkingstep>(p.main_workplan.its_elements[1]).its_operation = sn::OperationRef{4000000000u};
  EXPECT_THROW(write_stepnc(p, options()), std::out_of_range);
}

TEST(StepncStreamWriter, ElementByElementGivesTheWholeProjectsBytes) {
  const sn::Project whole = rapids(500, 12.5);
  std::string streamed;
  StepncStreamWriter writer(options(), [&](std::string_view chunk) { streamed += chunk; });
  sn::Project resources = whole;  // what a builder holds: no workplan, the security plane unknown
  resources.main_workplan.its_elements.clear();
  resources.setup.its_secplane = {};
  for (auto e : whole.main_workplan.its_elements) {
    std::get<sn::RapidMovement>(e).its_secplane = {};
    writer.element(resources, e);
  }
  const std::uint64_t bytes = writer.finish(whole);
  EXPECT_EQ(bytes, streamed.size());
  EXPECT_TRUE(streamed == write_stepnc(whole, options()));
  EXPECT_THROW(writer.finish(whole), std::logic_error);
}

}  // namespace
}  // namespace ncbridge::step_writer
