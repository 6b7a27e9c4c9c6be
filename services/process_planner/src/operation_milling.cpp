// Faces, pockets, slots, steps and the outside profile (docs/plan.md, "Operations").
#include <algorithm>
#include <cmath>
#include <limits>

#include "feature_geometry.hpp"
#include "ncbridge/common/error.hpp"
#include "operation_plan.hpp"
#include "tool_choice.hpp"

namespace ncbridge::process_planner {

namespace pr = part_reader;
namespace sn = stepnc;

namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

double tidy(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0 ? 0 : r;
}

[[noreturn]] void cannot(const PlanContext& c, const pr::Feature& f, const std::string& id, const std::string& needs) {
  throw InputError({c.part.file, f.line, 0}, feature_text(f, id) + ": " + needs);
}

std::string mm(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g mm", v);
  return buf;
}

template <class Op>
PlannedOperation milling(Phase phase, int rank, const setup::Tool& tool, Cut cut, const char* word, std::optional<sn::Two5DMillingStrategy> strategy,
                         double axial, std::optional<double> radial, std::optional<double> side, std::optional<double> bottom,
                         const Options& options) {
  Op op;
  op.retract_plane = tidy(options.retract_clearance);
  op.its_machining_strategy = strategy;
  op.axial_cutting_depth = tidy(axial);
  if (radial) op.radial_cutting_depth = tidy(*radial);
  if (side) op.allowance_side = tidy(*side);
  if (bottom) op.allowance_bottom = tidy(*bottom);
  return {phase, rank, &tool, cut, word, op};
}

const sn::ContourParallel kClimbInside{sn::RotDirection::Ccw, sn::CutmodeType::Climb};
const sn::ContourParallel kClimbOutside{sn::RotDirection::Cw, sn::CutmodeType::Climb};

// The corners of an outline a cutter inside it must fit, leaving out those on open edges.
double inner_corner(const std::vector<pr::OutlineVertex>& outline) {
  bool any_open = false;
  for (const auto& v : outline) any_open = any_open || v.open;
  if (!any_open) return tightest_corner(outline, true);
  // Walls only: the runs of closed edges, each on its own.
  double tightest = 1e9;
  const std::size_t n = outline.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = outline[i];
    if (a.open) continue;
    if (a.bulge > 0) {
      const auto& b = outline[(i + 1) % n];
      const double chord = std::hypot(b.x - a.x, b.y - a.y);
      const double sweep = 4 * std::atan(a.bulge);
      tightest = std::min(tightest, chord / (2 * std::sin(sweep / 2)));
    }
    // A sharp corner between two walls.
    const auto& next = outline[(i + 1) % n];
    if (next.open || a.bulge != 0 || next.bulge != 0) continue;
    const auto& c = outline[(i + 2) % n];
    const double ux = next.x - a.x, uy = next.y - a.y, vx = c.x - next.x, vy = c.y - next.y;
    if (ux * vy - uy * vx > 1e-9 * std::hypot(ux, uy) * std::hypot(vx, vy)) tightest = 0;
  }
  return tightest;
}

}  // namespace

std::vector<PlannedOperation> plan_face(const pr::Feature& f, const std::string& id, const PlanContext& c) {
  const setup::Tool* tool = face_tool(c.tools);
  if (!tool) cannot(c, f, id, "needs a face mill or a flat end mill");
  const double limit = axial_limit(*tool, tool->type == setup::ToolType::FaceMill ? 0.2 : 0.5);
  const sn::Bidirectional along{sn::Direction{0, 1, 0}, sn::LeftOrRight::Right};
  std::vector<PlannedOperation> ops;
  const double finish = c.options.bottom_allowance;
  if (f.depth > finish + 1.0) {
    ops.push_back(milling<sn::PlaneRoughMilling>(Phase::Facing, 0, *tool, Cut::Facing, "ROUGH", along, std::min(limit, f.depth - finish),
                                                 std::nullopt, std::nullopt, finish, c.options));
    ops.push_back(milling<sn::PlaneFinishMilling>(Phase::Facing, 1, *tool, Cut::Facing, "FINISH", along, finish, std::nullopt,
                                                  std::nullopt, std::nullopt, c.options));
  } else {
    ops.push_back(milling<sn::PlaneFinishMilling>(Phase::Facing, 1, *tool, Cut::Facing, "FINISH", along, std::min(limit, f.depth),
                                                  std::nullopt, std::nullopt, std::nullopt, c.options));
  }
  return ops;
}

std::vector<PlannedOperation> plan_pocket(const pr::Feature& f, const std::string& id, const PlanContext& c) {
  const auto outline = local_outline(f);
  const double corner = f.outline == pr::Outline::Circle ? f.diameter / 2 : inner_corner(outline);
  const double width = narrowest(f);
  const bool open = f.kind == pr::FeatureKind::OpenPocket;
  // Room to move: a closed pocket's cutter must be narrower than the pocket.
  const double room = open ? width : width - 1.0;
  const setup::Tool* tool = nullptr;
  if (corner <= 1e-6) {
    tool = smallest_end_mill(c.tools, f.depth);
    if (tool && tool->diameter <= room) {
      c.warnings.push_back({f.source, id + ": sharp inner corners: the " + mm(tool->diameter) + " end mill leaves them rounded to " +
                                          mm(tool->diameter / 2)});
    } else {
      tool = nullptr;
    }
  } else {
    tool = end_mill(c.tools, std::min(2 * corner, room), f.depth);
  }
  if (!tool) {
    cannot(c, f, id, "needs a flat end mill of at most " + mm(std::max(0.0, std::min(corner > 1e-6 ? 2 * corner : room, room))) +
                         " (corner radius " + mm(corner) + ") with flutes reaching " + mm(f.depth));
  }
  const double rough_axial = std::min(axial_limit(*tool, 0.5), f.depth);
  const double finish_axial = tool->flute_length <= 0 || tool->flute_length >= f.depth ? f.depth : axial_limit(*tool, 1.0);
  const double bottom = f.through ? 0.0 : c.options.bottom_allowance;
  std::optional<sn::Two5DMillingStrategy> rough = kClimbInside;
  if (open) rough = sn::Bidirectional{sn::Direction{1, 0, 0}, sn::LeftOrRight::Left};
  return {milling<sn::BottomAndSideRoughMilling>(Phase::Roughing, 0, *tool, Cut::Milling, "ROUGH", rough, rough_axial,
                                                 0.5 * tool->diameter, c.options.side_allowance, bottom, c.options),
          milling<sn::BottomAndSideFinishMilling>(Phase::Finishing, 0, *tool, Cut::Milling, "FINISH", kClimbInside, finish_axial,
                                                  c.options.side_allowance, std::nullopt, std::nullopt, c.options)};
}

std::vector<PlannedOperation> plan_slot(const pr::Feature& f, const std::string& id, const PlanContext& c) {
  if (const setup::Tool* exact = end_mill_of(c.tools, f.width, f.depth)) {
    return {milling<sn::BottomAndSideFinishMilling>(Phase::Roughing, 0, *exact, Cut::Slotting, "MILL", sn::CenterMilling{},
                                                    std::min(axial_limit(*exact, 0.5), f.depth), std::nullopt, std::nullopt,
                                                    std::nullopt, c.options)};
  }
  const setup::Tool* tool = end_mill(c.tools, f.width - 0.5, f.depth);
  if (!tool) cannot(c, f, id, "needs a flat end mill of " + mm(f.width) + " or of at most " + mm(f.width - 0.5) + " with flutes reaching " + mm(f.depth));
  const double bottom = f.through ? 0.0 : c.options.bottom_allowance;
  const double finish_axial = tool->flute_length <= 0 || tool->flute_length >= f.depth ? f.depth : axial_limit(*tool, 1.0);
  return {milling<sn::BottomAndSideRoughMilling>(Phase::Roughing, 0, *tool, Cut::Slotting, "ROUGH",
                                                 sn::Bidirectional{sn::Direction{1, 0, 0}, sn::LeftOrRight::Left},
                                                 std::min(axial_limit(*tool, 0.5), f.depth), 0.5 * tool->diameter, c.options.side_allowance,
                                                 bottom, c.options),
          milling<sn::BottomAndSideFinishMilling>(Phase::Finishing, 0, *tool, Cut::Milling, "FINISH", kClimbInside, finish_axial,
                                                  c.options.side_allowance, std::nullopt, std::nullopt, c.options)};
}

std::vector<PlannedOperation> plan_step(const pr::Feature& f, const std::string& id, const PlanContext& c) {
  const setup::Tool* tool = end_mill(c.tools, std::max(2 * f.width, 1.0), f.depth);
  if (!tool) tool = end_mill(c.tools, kNone, f.depth);
  if (!tool) cannot(c, f, id, "needs a flat end mill with flutes reaching " + mm(f.depth));
  const double finish_axial = tool->flute_length <= 0 || tool->flute_length >= f.depth ? f.depth : axial_limit(*tool, 1.0);
  return {milling<sn::BottomAndSideRoughMilling>(Phase::Roughing, 0, *tool, Cut::Milling, "ROUGH",
                                                 sn::Bidirectional{sn::Direction{1, 0, 0}, sn::LeftOrRight::Left},
                                                 std::min(axial_limit(*tool, 0.5), f.depth), 0.6 * tool->diameter, c.options.side_allowance,
                                                 c.options.bottom_allowance, c.options),
          milling<sn::BottomAndSideFinishMilling>(Phase::Finishing, 0, *tool, Cut::Milling, "FINISH",
                                                  sn::Unidirectional{sn::Direction{1, 0, 0}, sn::CutmodeType::Climb}, finish_axial,
                                                  c.options.side_allowance, std::nullopt, std::nullopt, c.options)};
}

std::vector<PlannedOperation> plan_outside_profile(const pr::Feature& f, const std::string& id, const PlanContext& c) {
  const double corner = tightest_corner(local_outline(f), false);
  const setup::Tool* tool = nullptr;
  if (corner <= 1e-6) {
    tool = smallest_end_mill(c.tools, f.depth);
    if (tool) {
      c.warnings.push_back({f.source, id + ": sharp inside corners of the outline: the " + mm(tool->diameter) +
                                          " end mill leaves them rounded to " + mm(tool->diameter / 2)});
    }
  } else {
    tool = end_mill(c.tools, 2 * corner, f.depth);
  }
  if (!tool) {
    // Sharp inside corners take any diameter (left rounded to its radius); straight or convex
    // outlines too.
    const bool any_diameter = corner <= 1e-6 || corner >= 1e8;
    cannot(c, f, id, "needs a flat end mill" + (any_diameter ? std::string() : " of at most " + mm(2 * corner)) + " with flutes reaching " +
                         mm(f.depth));
  }
  const double finish_axial = tool->flute_length <= 0 || tool->flute_length >= f.depth ? f.depth : axial_limit(*tool, 1.0);
  return {milling<sn::SideRoughMilling>(Phase::Roughing, 0, *tool, Cut::Milling, "ROUGH", kClimbOutside,
                                        std::min(axial_limit(*tool, 1.0), f.depth), 0.5 * tool->diameter, c.options.side_allowance,
                                        std::nullopt, c.options),
          milling<sn::SideFinishMilling>(Phase::Finishing, 0, *tool, Cut::Milling, "FINISH", kClimbOutside, finish_axial,
                                         c.options.side_allowance, std::nullopt, std::nullopt, c.options)};
}

}  // namespace ncbridge::process_planner
