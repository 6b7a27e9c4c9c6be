#include "ncbridge/feature_recognizer/cc1_input.hpp"

#include <cmath>
#include <type_traits>

namespace ncbridge::feature_recognizer {
namespace {

setup::ToolType tool_type(stepnc::ToolBody body) {
  using B = stepnc::ToolBody;
  using T = setup::ToolType;
  switch (body) {
    case B::Facemill: return T::FaceMill;
    case B::Endmill: return T::FlatEndMill;
    case B::BallEndmill: return T::BallEndMill;
    case B::BullnoseEndmill: return T::BullNoseEndMill;
    case B::TSlotMill: return T::TSlotMill;
    case B::TwistDrill: return T::Drill;
    case B::Centerdrill: return T::CenterDrill;
    case B::Countersink: return T::ChamferMill;
    case B::Reamer: return T::Reamer;
    case B::Tap: return T::Tap;
    case B::BoringTool: return T::BoringBar;
    case B::UserDefinedTool: return T::Unknown;
  }
  return T::Unknown;
}

setup::Tool tool_of(const stepnc::MillingCuttingTool& t) {
  setup::Tool tool;
  tool.number = t.number;
  tool.name = t.its_id;
  tool.type = tool_type(t.body);
  tool.diameter = t.dimension.diameter;
  tool.corner_radius = t.dimension.edge_radius.value_or(0);
  if (t.dimension.tool_tip_half_angle) tool.point_angle = 2 * *t.dimension.tool_tip_half_angle;
  tool.length = t.tool_offset_length;
  return tool;
}

Point3 point(const stepnc::CartesianPoint& p) { return {p.x, p.y, p.z}; }

constexpr int kUnnumberedTools = 10000;

// The canned-cycle G code the drilling-family operation stands for.
std::uint16_t cycle_code(const stepnc::Operation& op) {
  return std::visit(
      [](const auto& o) -> std::uint16_t {
        using O = std::decay_t<decltype(o)>;
        if constexpr (std::is_same_v<O, stepnc::MultistepDrilling>) return 830;
        else if constexpr (std::is_same_v<O, stepnc::Reaming>) return 850;
        else if constexpr (std::is_same_v<O, stepnc::Boring> || std::is_same_v<O, stepnc::BackBoring>) return 860;
        else if constexpr (std::is_same_v<O, stepnc::Tapping>) return 840;
        else return 810;
      },
      op);
}

// B-spline toolpaths (G5, G5.1, G5.2 NURBS) are followed as chords this close to the curve.
constexpr double kSplineChordTolerance = 0.001;  // mm

void append_curve(const stepnc::CompositeCurve& curve, bool rapid, Point3& at, std::vector<Move>& moves) {
  for (const auto& segment : curve.segments) {
    const auto* spline = std::get_if<stepnc::BSplineCurve>(&segment);
    const std::vector<stepnc::CartesianPoint> spline_points =
        spline ? stepnc::bspline_polyline(*spline, kSplineChordTolerance) : std::vector<stepnc::CartesianPoint>{};
    const auto* line = std::get_if<stepnc::Polyline>(&segment);
    if (line || spline) {
      for (const auto& p : line ? line->points : spline_points) {
        const Point3 q = point(p);
        if (q == at) continue;
        Move m;
        m.kind = rapid ? MoveKind::Rapid : MoveKind::Linear;
        m.end = q;
        moves.push_back(m);
        at = q;
      }
      continue;
    }
    const auto& arc = std::get<stepnc::TrimmedCircle>(segment);
    const auto& axis = arc.position.axis;
    Move m;
    m.end = point(arc.trim_2_point);
    if (std::abs(axis.x) < 1e-9 && std::abs(axis.y) < 1e-9 && !rapid) {
      m.kind = MoveKind::Arc;
      m.center_x = arc.position.location.x;
      m.center_y = arc.position.location.y;
      m.clockwise = arc.sense_agreement != (axis.z > 0);
    } else {
      m.kind = rapid ? MoveKind::Rapid : MoveKind::Linear;  // not in XY: its chord
    }
    if (!(point(arc.trim_1_point) == at)) {
      Move to_start;
      to_start.kind = rapid ? MoveKind::Rapid : MoveKind::Linear;
      to_start.end = point(arc.trim_1_point);
      moves.push_back(to_start);
    }
    moves.push_back(m);
    at = m.end;
  }
}

}  // namespace

std::vector<ToolpathWorkingstep> workingsteps_from_cc1(const stepnc::Project& cc1) {
  std::vector<ToolpathWorkingstep> out;
  Point3 at;
  std::vector<Move> pending_rapids;
  Point3 pending_start;
  for (const auto& element : cc1.main_workplan.its_elements) {
    if (const auto* rapid = std::get_if<stepnc::RapidMovement>(&element)) {
      if (pending_rapids.empty()) pending_start = at;
      if (rapid->its_toolpath) {
        for (const auto& t : rapid->its_toolpath->its_list) append_curve(t.basiccurve, true, at, pending_rapids);
      }
      continue;
    }
    if (const auto* probing = std::get_if<stepnc::WorkpieceProbing>(&element)) {
      // Not machining: the tool goes to the probe's start and then along its travel.
      const auto& s = probing->start_position.location;
      const auto& d = probing->its_direction;
      const double travel = probing->expected_value.theoretical_size + probing->expected_value.upper_limit;
      if (pending_rapids.empty()) pending_start = at;
      for (const Point3& q : {point(s), Point3{s.x + d.x * travel, s.y + d.y * travel, s.z + d.z * travel}}) {
        if (q == at) continue;
        Move m;
        m.kind = MoveKind::Rapid;
        m.end = q;
        pending_rapids.push_back(m);
        at = q;
      }
      continue;
    }
    const auto& step = std::get<stepnc::MachiningWorkingstep>(element);
    const auto& op = cc1.operation(step.its_operation);
    const auto& mop = stepnc::machining_operation(op);
    ToolpathWorkingstep ws;
    ws.tool = tool_of(cc1.tool(mop.its_tool));
    // Files from elsewhere name tools without a T number: keep them apart (runs of one tool
    // make one operation) with a number no program uses.
    if (ws.tool.number == 0) ws.tool.number = kUnnumberedTools + static_cast<int>(mop.its_tool.index) + 1;
    const auto& tech = cc1.technology(mop.its_technology);
    ws.feed = tech.feedrate.value_or(0) * 60000;
    ws.spindle_rpm = std::abs(tech.spindle.value_or(0)) * 60;
    ws.start = pending_rapids.empty() ? at : pending_start;
    ws.moves = std::move(pending_rapids);
    pending_rapids.clear();
    for (auto& m : ws.moves) m.source_line = step.source.first_line;

    const auto& feature = cc1.feature(step.its_feature);
    const auto* hole = std::get_if<stepnc::RoundHole>(&feature);
    const auto* drilling = std::visit(
        [](const auto& o) -> const stepnc::DrillingTypeOperation* {
          if constexpr (std::is_base_of_v<stepnc::DrillingTypeOperation, std::decay_t<decltype(o)>>) return &o;
          else return nullptr;
        },
        op);
    if (hole && drilling) {
      const auto& placement = hole->feature_placement;
      const double sign = placement.axis.z < 0 ? -1 : 1;
      const double top = placement.location.z;
      const double bottom = top + sign * hole->depth.position.location.z;
      const double clear = top + sign * mop.retract_plane.value_or(0);
      canonical::CycleTag tag;
      tag.g_code_x10 = cycle_code(op);
      tag.x = placement.location.x, tag.y = placement.location.y;
      tag.r = clear, tag.z = bottom;
      tag.cycle_id = static_cast<std::uint32_t>(out.size() + 1);
      ws.cycle = tag;
      Move down{MoveKind::Rapid, {tag.x, tag.y, clear}};
      Move feed{MoveKind::Linear, {tag.x, tag.y, bottom}};
      Move up{MoveKind::Rapid, {tag.x, tag.y, clear}};
      for (auto* m : {&down, &feed, &up}) {
        m->source_line = step.source.first_line;
        ws.moves.push_back(*m);
      }
      at = up.end;
    } else if (mop.its_toolpath) {
      for (const auto& t : mop.its_toolpath->its_list) {
        const bool rapid = t.its_type == stepnc::ToolpathType::Connect || t.its_type == stepnc::ToolpathType::NonContact;
        const std::size_t before = ws.moves.size();
        append_curve(t.basiccurve, rapid, at, ws.moves);
        for (std::size_t i = before; i < ws.moves.size(); ++i) ws.moves[i].source_line = step.source.first_line;
      }
    }
    out.push_back(std::move(ws));
  }
  return out;
}

std::optional<setup::Stock> stock_from_cc1(const stepnc::Project& cc1) {
  if (!cc1.rawpiece || !cc1.rawpiece->its_bounding_geometry) return std::nullopt;
  const auto& block = *cc1.rawpiece->its_bounding_geometry;
  const auto& o = block.position.location;
  setup::Stock stock;
  stock.min = {o.x, o.y, o.z};
  stock.max = {o.x + block.x, o.y + block.y, o.z + block.z};
  return stock;
}

}  // namespace ncbridge::feature_recognizer
