// The model codec round-trips every feature and operation type of the model with every
// attribute set away from its default, so an attribute the codec forgets (REGION's projection
// was one) changes the decoded project and fails here. The test also checks that it holds one
// of each alternative of stepnc::Feature, stepnc::Operation, the profiles and the strategies,
// so a type added to the model without a line here fails too.
#include <gtest/gtest.h>

#include <set>
#include <variant>

#include "ncbridge/stepnc_codec/project_codec.hpp"

namespace ncbridge {
namespace {

using namespace stepnc;

Axis2Placement3d placement(double k) { return {{k, k + 0.5, -k}, {0, 1, 0}, {0, 0, -1}}; }
TolerancedLengthMeasure measure(double k) { return {k, 0.01 * k, -0.02 * k, 5}; }
CompositeCurve curve(double k) {
  TrimmedCircle arc{placement(k), 2.5 * k, {k, 0, 0}, 0.25, {0, k, 0}, 1.75, false};
  BSplineCurve spline{2, {{k, k, 0}, {k, 2 * k, 0}, {3 * k, k, 0}}, {3, 3}, {0, k}, KnotType::PiecewiseBezierKnots,
                      {1, 0.5 * k, 1}};
  return {{Polyline{{{0, 0, k}, {k, 1, k}, {k, k, k}}}, arc, spline}};
}
LinearPath path(double k) { return {placement(k), measure(k), {0, 1, 0}}; }
template <class F> F feature(double k) {
  F f;
  f.its_id = "feature " + std::to_string(k);
  f.feature_placement = placement(k);
  f.depth.position = placement(-k);
  return f;
}

std::vector<Feature> every_feature() {
  std::vector<Feature> out;
  out.emplace_back(feature<ToolpathFeature>(1));
  for (HoleBottomCondition bottom : {HoleBottomCondition{ThroughBottomCondition{}}, HoleBottomCondition{FlatHoleBottom{}},
                                     HoleBottomCondition{ConicalHoleBottom{90}}}) {
    auto hole = feature<RoundHole>(2);
    hole.diameter = measure(6);
    hole.bottom_condition = bottom;
    out.emplace_back(hole);
  }
  const std::vector<ClosedProfile> closed{RectangularClosedProfile{placement(3), measure(30), measure(20)},
                                          CircularClosedProfile{placement(4), measure(12)},
                                          GeneralClosedProfile{placement(5), curve(5)}};
  for (const ClosedProfile& boundary : closed) {
    auto face = feature<PlanarFace>(3);
    face.course_of_travel = path(3);
    face.removal_boundary = {placement(3.5), 42};
    face.face_boundary = boundary;
    out.emplace_back(face);
    auto pocket = feature<ClosedPocket>(4);
    pocket.slope = 3;
    pocket.bottom_condition = ThroughPocketBottomCondition{};
    pocket.planar_radius = measure(1);
    pocket.orthogonal_radius = measure(2);
    pocket.feature_boundary = boundary;
    out.emplace_back(pocket);
  }
  for (const OpenProfile& open : {OpenProfile{LinearProfile{placement(6), 17}}, OpenProfile{GeneralProfile{placement(7), curve(7)}}}) {
    auto pocket = feature<OpenPocket>(5);
    pocket.slope = 1;
    pocket.planar_radius = measure(3);
    pocket.orthogonal_radius = measure(4);
    pocket.open_boundary = open;
    pocket.wall_boundary = open;
    out.emplace_back(pocket);
    auto slot = feature<Slot>(6);
    slot.course_of_travel = path(6);
    slot.swept_shape = open;
    slot.end_conditions = {SlotEndType::Radiused, SlotEndType::Woodruff};
    out.emplace_back(slot);
  }
  auto step = feature<Step>(7);
  step.open_boundary = path(7);
  out.emplace_back(step);
  auto profile = feature<GeneralOutsideProfile>(8);
  profile.profile_swept_shape = path(8);
  profile.feature_boundary = curve(8);
  profile.closed = false;
  out.emplace_back(profile);
  Region region;
  region.its_id = "region";
  region.feature_placement = placement(9);
  region.proj_curve = curve(9);
  region.proj_dir = {0, -1, 0};
  region.depth = measure(9);
  out.emplace_back(region);
  return out;
}

MachiningOperation machining(double k) {
  MachiningOperation m;
  CutterLocationTrajectory t;
  t.its_priority = false;
  t.its_type = ToolpathType::Lift;
  t.its_technology = TechnologyRef{1};
  t.its_machine_functions = MachineFunctionsRef{1};
  t.its_direction = false;
  t.basiccurve = curve(k);
  m.its_toolpath = ToolpathList{{t, t}};
  m.its_id = "operation " + std::to_string(k);
  m.retract_plane = k;
  m.start_point = CartesianPoint{k, -k, 2 * k};
  m.its_tool = ToolRef{1};
  m.its_technology = TechnologyRef{1};
  m.its_machine_functions = MachineFunctionsRef{1};
  m.overcut_length = 0.5 * k;
  return m;
}

template <class O> O two5d(double k, Two5DMillingStrategy strategy) {
  O o;
  static_cast<MachiningOperation&>(o) = machining(k);
  o.its_machining_strategy = strategy;
  o.axial_cutting_depth = 1.5;
  o.radial_cutting_depth = 4;
  o.allowance_side = 0.2;
  o.allowance_bottom = 0.1;
  return o;
}

template <class O> O drilling(double k) {
  O o;
  static_cast<MachiningOperation&>(o) = machining(k);
  o.cutting_depth = 12;
  o.previous_diameter = 3;
  o.dwell_time_bottom = 0.5;
  o.feed_on_retract = 2;
  o.its_machining_strategy = DrillingTypeStrategy{0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  return o;
}

template <class O> O boring(double k) {
  O o = drilling<O>(k);
  o.spindle_stop_at_bottom = true;
  o.depth_of_testcut = 0.7;
  o.waiting_position = CartesianPoint{1, 2, 3};
  return o;
}

std::vector<Operation> every_operation() {
  std::vector<Operation> out;
  FreeformOperation freeform;
  static_cast<MachiningOperation&>(freeform) = machining(1);
  out.emplace_back(freeform);
  out.emplace_back(drilling<Drilling>(2));
  out.emplace_back(drilling<CenterDrilling>(3));
  auto peck = drilling<MultistepDrilling>(4);
  peck.retract_distance = 1;
  peck.first_depth = 2;
  peck.depth_of_step = 3;
  peck.dwell_time_step = 0.25;
  out.emplace_back(peck);
  out.emplace_back(boring<Boring>(5));
  out.emplace_back(boring<Reaming>(6));
  out.emplace_back(drilling<BackBoring>(7));
  auto tap = drilling<Tapping>(8);
  tap.compensation_chuck = true;
  out.emplace_back(tap);
  const std::vector<Two5DMillingStrategy> strategies{
      Unidirectional{Direction{1, 0, 0}, CutmodeType::Conventional},
      Bidirectional{Direction{0, 1, 0}, LeftOrRight::Right},
      ContourParallel{RotDirection::Cw, CutmodeType::Climb},
      ContourSpiral{RotDirection::Ccw, CutmodeType::Conventional},
      CenterMilling{}};
  for (const Two5DMillingStrategy& s : strategies) {
    out.emplace_back(two5d<PlaneRoughMilling>(9, s));
    out.emplace_back(two5d<PlaneFinishMilling>(10, s));
    out.emplace_back(two5d<SideRoughMilling>(11, s));
    out.emplace_back(two5d<SideFinishMilling>(12, s));
    out.emplace_back(two5d<BottomAndSideRoughMilling>(13, s));
    out.emplace_back(two5d<BottomAndSideFinishMilling>(14, s));
  }
  return out;
}

Project every_type_project() {
  Project p;
  p.its_id = "every type";
  p.features = every_feature();
  p.operations = every_operation();
  p.tools.resize(2);
  p.technologies.resize(2);
  p.machine_functions.resize(2);
  for (std::size_t i = 0; i < p.operations.size(); ++i) {
    MachiningWorkingstep ws;
    ws.its_id = "ws" + std::to_string(i);
    ws.its_secplane.position = placement(static_cast<double>(i));
    ws.its_feature = FeatureRef{static_cast<std::uint32_t>(i % p.features.size())};
    ws.its_operation = OperationRef{static_cast<std::uint32_t>(i)};
    ws.source = {1, static_cast<std::uint32_t>(i + 1), static_cast<std::uint32_t>(i + 3)};
    p.main_workplan.its_elements.emplace_back(ws);
  }
  RapidMovement rapid;
  rapid.its_id = "rapid";
  rapid.its_toolpath = machining(3).its_toolpath;
  p.main_workplan.its_elements.emplace_back(rapid);
  WorkpieceProbing probing;
  probing.its_id = "probing";
  probing.its_secplane.position = placement(7);
  probing.measured_offset = {"#5063", 1.5};
  probing.start_position = placement(8);
  probing.its_direction = {0, 0, -1};
  probing.expected_value = measure(9);
  probing.its_probe = "T99";
  probing.source = {2, 40, 41};
  p.main_workplan.its_elements.emplace_back(probing);
  return p;
}

template <class V, class Items, class Get>
std::set<std::size_t> alternatives(const Items& items, Get get) {
  std::set<std::size_t> seen;
  for (const auto& item : items) {
    if (const V* v = get(item)) seen.insert(v->index());
  }
  return seen;
}

std::set<std::size_t> all_of(std::size_t n) {
  std::set<std::size_t> s;
  for (std::size_t i = 0; i < n; ++i) s.insert(i);
  return s;
}

TEST(StepncCodecEveryType, HoldsEveryAlternativeOfTheModel) {
  const Project p = every_type_project();
  EXPECT_EQ(alternatives<Executable>(p.main_workplan.its_elements, [](const Executable& e) { return &e; }),
            all_of(std::variant_size_v<Executable>));
  const auto segments = alternatives<CurveSegment>(p.operations, [](const Operation& o) -> const CurveSegment* {
    const auto& toolpath = machining_operation(o).its_toolpath;
    return toolpath && !toolpath->its_list.empty() && toolpath->its_list[0].basiccurve.segments.size() > 2
               ? &toolpath->its_list[0].basiccurve.segments[2] : nullptr;
  });
  EXPECT_EQ(segments, (std::set<std::size_t>{2}));  // curve()'s third segment is a B-spline
  EXPECT_EQ(alternatives<Feature>(p.features, [](const Feature& f) { return &f; }), all_of(std::variant_size_v<Feature>));
  EXPECT_EQ(alternatives<Operation>(p.operations, [](const Operation& o) { return &o; }),
            all_of(std::variant_size_v<Operation>));
  const auto closed = alternatives<ClosedProfile>(p.features, [](const Feature& f) -> const ClosedProfile* {
    const auto* pocket = std::get_if<ClosedPocket>(&f);
    return pocket ? &pocket->feature_boundary : nullptr;
  });
  EXPECT_EQ(closed, all_of(std::variant_size_v<ClosedProfile>));
  const auto open = alternatives<OpenProfile>(p.features, [](const Feature& f) -> const OpenProfile* {
    const auto* slot = std::get_if<Slot>(&f);
    return slot ? &slot->swept_shape : nullptr;
  });
  EXPECT_EQ(open, all_of(std::variant_size_v<OpenProfile>));
  const auto strategies = alternatives<Two5DMillingStrategy>(p.operations, [](const Operation& o) -> const Two5DMillingStrategy* {
    const auto* m = std::get_if<PlaneRoughMilling>(&o);
    return m && m->its_machining_strategy ? &*m->its_machining_strategy : nullptr;
  });
  EXPECT_EQ(strategies, all_of(std::variant_size_v<Two5DMillingStrategy>));
  const auto bottoms = alternatives<HoleBottomCondition>(p.features, [](const Feature& f) -> const HoleBottomCondition* {
    const auto* h = std::get_if<RoundHole>(&f);
    return h ? &h->bottom_condition : nullptr;
  });
  EXPECT_EQ(bottoms, all_of(std::variant_size_v<HoleBottomCondition>));
}

TEST(StepncCodecEveryType, RoundTripsEveryFeatureAndOperationType) {
  const Project p = every_type_project();
  const std::string bytes = stepnc_codec::encode_project(p);
  const Project back = stepnc_codec::decode_project(bytes);
  ASSERT_EQ(back.features.size(), p.features.size());
  for (std::size_t i = 0; i < p.features.size(); ++i)
    EXPECT_EQ(back.features[i], p.features[i]) << entity_name(p.features[i]) << " #" << i;
  ASSERT_EQ(back.operations.size(), p.operations.size());
  for (std::size_t i = 0; i < p.operations.size(); ++i)
    EXPECT_EQ(back.operations[i], p.operations[i]) << entity_name(p.operations[i]) << " #" << i;
  EXPECT_EQ(back, p);
  EXPECT_EQ(stepnc_codec::encode_project(back), bytes);
}

TEST(StepncCodecEveryType, RegionKeepsItsProjection) {
  Project p;
  Region region;
  region.its_id = "r";
  region.proj_curve = curve(2);
  region.proj_dir = {1, 0, 0};
  region.depth = measure(4);
  p.features.emplace_back(region);
  const auto back = std::get<Region>(stepnc_codec::decode_project(stepnc_codec::encode_project(p)).features.at(0));
  EXPECT_EQ(back.proj_curve, region.proj_curve);
  EXPECT_EQ(back.proj_dir, region.proj_dir);
  EXPECT_EQ(back.depth, region.depth);
}

}  // namespace
}  // namespace ncbridge
