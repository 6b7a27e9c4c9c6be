// Round holes (docs/plan.md, "Holes"): centre drilling, drilling or peck drilling with a drill of
// the hole's size, pre-drilling and reaming where the tolerance asks or only a reamer fits,
// helical milling where no drill does, counterbores milled flat.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ncbridge/common/error.hpp"
#include "operation_plan.hpp"
#include "tool_choice.hpp"

namespace ncbridge::process_planner {

namespace pr = part_reader;
namespace sn = stepnc;

namespace {

double tidy(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0 ? 0 : r;
}

std::string mm(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g mm", v);
  return buf;
}

// Ranks within the holes phase: counterbores milled first (so what is drilled below them starts
// in air), then centre drilling, drilling, helical milling, reaming, flattening of blind holes.
enum Rank : int { kCounterbore = 0, kCounterboreFinish, kCenter, kDrill, kHelical, kHelicalFinish, kReam, kFlatten, kCountersink };

double tip_length(const setup::Tool& drill, double diameter) {
  const double angle = drill.point_angle > 0 ? drill.point_angle : 118.0;
  return diameter / 2 / std::tan(angle / 2 * std::numbers::pi / 180);
}

template <class Op>
Op drilling_type(double cutting_depth, const Options& options) {
  Op op;
  op.retract_plane = tidy(options.retract_clearance);
  op.cutting_depth = tidy(cutting_depth);
  return op;
}

PlannedOperation center(const setup::Tool& tool, const pr::Feature& f, const Options& options) {
  const double angle = tool.point_angle > 0 ? tool.point_angle : tool.type == setup::ToolType::CenterDrill ? 60.0 : 90.0;
  const double mark = 0.5 * std::min(f.diameter, tool.diameter);
  const double depth = mark / 2 / std::tan(angle / 2 * std::numbers::pi / 180);
  return {Phase::Holes, kCenter, &tool, Cut::CenterDrilling, "CENTER DRILL", drilling_type<sn::CenterDrilling>(depth, options)};
}

// Drilling to `depth` (from the hole's top to the drill's point), pecked when deep.
PlannedOperation drill_to(const setup::Tool& drill, double depth, const Options& options) {
  if (depth > options.peck_ratio * drill.diameter) {
    auto op = drilling_type<sn::MultistepDrilling>(depth, options);
    op.first_depth = tidy(drill.diameter);
    op.depth_of_step = tidy(drill.diameter);
    op.retract_distance = tidy(drill.diameter + options.retract_clearance);  // back out of the hole each peck
    return {Phase::Holes, kDrill, &drill, Cut::Drilling, "PECK DRILL", op};
  }
  return {Phase::Holes, kDrill, &drill, Cut::Drilling, "DRILL", drilling_type<sn::Drilling>(depth, options)};
}

// How deep the drill's point goes: through holes break through with the full diameter plus 1 mm;
// blind holes end at their depth (a conical bottom is the drill's own point).
double drill_depth(const setup::Tool& drill, const pr::Feature& f) {
  if (f.bottom == pr::HoleBottom::Through) return f.depth + tip_length(drill, drill.diameter) + 1.0;
  return f.depth;
}

template <class Op>
PlannedOperation hole_milling(Rank rank, const setup::Tool& tool, const char* word, std::optional<sn::Two5DMillingStrategy> strategy,
                              double axial, double radial, std::optional<double> side, std::optional<double> bottom, const Options& options) {
  Op op;
  op.retract_plane = tidy(options.retract_clearance);
  op.its_machining_strategy = strategy;
  op.axial_cutting_depth = tidy(axial);
  op.radial_cutting_depth = tidy(radial);
  if (side) op.allowance_side = tidy(*side);
  if (bottom) op.allowance_bottom = tidy(*bottom);
  return {Phase::Holes, rank, &tool, Cut::HoleMilling, word, op};
}

// A hole milled out with an end mill going round on a helix: rough, then the wall and floor
// finished.
std::vector<PlannedOperation> helical(const setup::Tool& tool, const pr::Feature& f, bool counterbore, const Options& options) {
  const double finish = std::min(options.side_allowance, 0.2);
  const bool through = f.bottom == pr::HoleBottom::Through;
  const double pitch = std::min(axial_limit(tool, 0.3), f.depth);
  const Rank rough_rank = counterbore ? kCounterbore : kHelical, finish_rank = counterbore ? kCounterboreFinish : kHelicalFinish;
  return {hole_milling<sn::BottomAndSideRoughMilling>(rough_rank, tool, "ROUGH", sn::ContourSpiral{sn::RotDirection::Ccw, sn::CutmodeType::Climb},
                                                      pitch, 0.4 * tool.diameter, finish, through ? 0.0 : std::min(options.bottom_allowance, 0.2),
                                                      options),
          hole_milling<sn::BottomAndSideFinishMilling>(finish_rank, tool, "FINISH", sn::ContourParallel{sn::RotDirection::Ccw, sn::CutmodeType::Climb},
                                                       tool.flute_length <= 0 || tool.flute_length >= f.depth ? f.depth : axial_limit(tool, 1.0),
                                                       finish, std::nullopt, std::nullopt, options)};
}

}  // namespace

std::vector<PlannedOperation> plan_hole(const pr::Feature& f, const std::string& id, bool counterbore, const PlanContext& c) {
  const Options& o = c.options;
  const double d = f.diameter;
  auto cannot = [&](const std::string& needs) { throw InputError({c.part.file, f.line, 0}, feature_text(f, id) + ": " + needs); };
  std::vector<PlannedOperation> ops;

  if (counterbore) {  // milled flat to its depth, before the hole below it is drilled
    const setup::Tool* tool = end_mill(c.tools, d - 1.0, f.depth);
    if (!tool) cannot("a counterbore of " + mm(d) + " needs a flat end mill of at most " + mm(d - 1.0) + " with flutes reaching " + mm(f.depth));
    return helical(*tool, f, true, o);
  }

  const double band = f.diameter_tolerance ? std::abs(f.diameter_tolerance->first - f.diameter_tolerance->second) : 1e9;
  const bool tight = band < o.ream_band;
  const setup::Tool* drill = drill_of(c.tools, d);
  const setup::Tool* reamer = reamer_of(c.tools, d);
  const setup::Tool* before_ream = reamer ? pre_drill(c.tools, d) : nullptr;
  const setup::Tool* centering = centering_tool(c.tools);

  if (reamer && before_ream && (tight || !drill)) {
    if (centering) ops.push_back(center(*centering, f, o));
    ops.push_back(drill_to(*before_ream, drill_depth(*before_ream, f), o));
    auto ream = drilling_type<sn::Reaming>(f.bottom == pr::HoleBottom::Through ? f.depth + 1.0 : f.depth, o);
    ream.previous_diameter = tidy(before_ream->diameter);
    ream.feed_on_retract = 1.0;
    ops.push_back({Phase::Holes, kReam, reamer, Cut::Reaming, "REAM", ream});
    return ops;
  }
  if (tight) {
    c.warnings.push_back({f.source, id + ": its tolerance (" + mm(band) + " band) asks for reaming, but the tool list has no reamer of " + mm(d) +
                                        (reamer ? " with a drill 0.1 to 0.6 mm under size" : "") + ": " +
                                        (drill ? "drilled" : "milled")});
  }
  if (drill) {
    if (centering) ops.push_back(center(*centering, f, o));
    ops.push_back(drill_to(*drill, drill_depth(*drill, f), o));
    if (f.bottom == pr::HoleBottom::Flat || f.bottom == pr::HoleBottom::FlatWithRadius) {
      // The drill leaves its point in a flat-bottomed blind hole: an end mill flattens it.
      if (const setup::Tool* flat = end_mill(c.tools, d, f.depth)) {
        ops.push_back(hole_milling<sn::BottomAndSideFinishMilling>(kFlatten, *flat, "FINISH",
                                                                   sn::ContourParallel{sn::RotDirection::Ccw, sn::CutmodeType::Climb},
                                                                   std::min(axial_limit(*flat, 0.3), f.depth), 0.4 * flat->diameter,
                                                                   std::nullopt, std::nullopt, o));
      } else {
        c.warnings.push_back({f.source, id + ": flat bottom: no flat end mill of at most " + mm(d) +
                                            " to flatten it; the drill's point is left below the floor's edge"});
      }
    }
    return ops;
  }
  const setup::Tool* mill = end_mill(c.tools, d - 1.0, f.depth);
  if (!mill) {
    cannot("needs a drill of " + mm(d) + ", a reamer of " + mm(d) + " with a drill 0.1 to 0.6 mm under size, or a flat end mill of at most " +
           mm(d - 1.0) + " (helical milling) with flutes reaching " + mm(f.depth));
  }
  if (f.bottom == pr::HoleBottom::Conical) {
    c.warnings.push_back({f.source, id + ": conical bottom: helical milling leaves it flat"});
  }
  return helical(*mill, f, false, o);
}

std::vector<PlannedOperation> plan_countersink(const pr::Feature& f, const std::string& id, const PlanContext& c) {
  const double angle = f.tip_angle > 0 ? f.tip_angle : 90;
  const setup::Tool* tool = countersink_tool(c.tools, angle, f.diameter);
  if (!tool) {
    throw InputError({c.part.file, f.line, 0}, feature_text(f, id) + ": a countersink of " + mm(f.diameter) + " needs a countersink, chamfer mill or spot drill of " +
                                                   std::to_string(static_cast<int>(std::lround(angle))) + " degrees at least " + mm(f.diameter) + " wide");
  }
  // Sunk after the hole is drilled, to the cone's depth.
  return {{Phase::Holes, kCountersink, tool, Cut::CenterDrilling, "COUNTERSINK", drilling_type<sn::Drilling>(f.depth, c.options)}};
}

}  // namespace ncbridge::process_planner
