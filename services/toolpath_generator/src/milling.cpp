#include "milling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

#include "ncbridge/common/error.hpp"
#include "ncbridge/material_check/cutter_shape.hpp"

namespace ncbridge::toolpath_generator {

namespace {

namespace sn = stepnc;
constexpr double kPi = std::numbers::pi;

[[noreturn]] void fail(const Options& o, const MillingInput& in, const std::string& what) {
  throw InputError({o.source_name, 0, 0}, "workingstep '" + in.workingstep + "': " + what);
}

const sn::Two5DMillingOperation& milling_of(const sn::Operation& op) {
  return *std::visit(
      [](const auto& o) -> const sn::Two5DMillingOperation* {
        if constexpr (std::is_base_of_v<sn::Two5DMillingOperation, std::decay_t<decltype(o)>>) return &o;
        else return nullptr;
      },
      op);
}

bool roughing(const sn::Operation& op) {
  return std::holds_alternative<sn::PlaneRoughMilling>(op) || std::holds_alternative<sn::SideRoughMilling>(op) ||
         std::holds_alternative<sn::BottomAndSideRoughMilling>(op);
}

bool cuts_bottom(const sn::Operation& op) {
  return !std::holds_alternative<sn::SideRoughMilling>(op) && !std::holds_alternative<sn::SideFinishMilling>(op);
}

bool cuts_side(const sn::Operation& op) {
  return !std::holds_alternative<sn::PlaneRoughMilling>(op) && !std::holds_alternative<sn::PlaneFinishMilling>(op);
}

std::optional<double> overlap_of(const sn::Two5DMillingStrategy& s) {
  return std::visit([](const auto& x) { return x.overlap; }, s);
}

// The levels from the top down to the floor, `step` apart (the last one at the floor).
std::vector<double> levels(double top, double floor, double step) {
  std::vector<double> out;
  for (double z = top - step; z > floor + 1e-6; z -= step) out.push_back(z);
  out.push_back(floor);
  return out;
}

double direction_angle(const material_check::PlanarFrame& frame, const sn::Direction& d) {
  return frame.angle + std::atan2(d.y, d.x);
}

// The strategy a workingstep without one gets: faces are milled back and forth along their
// course, slots along their centre line (when as wide as the cutter), the rest by offsets.
sn::Two5DMillingStrategy default_strategy(const sn::Feature& f, double width_minus_cutter) {
  if (std::holds_alternative<sn::PlanarFace>(f)) return sn::Bidirectional{};
  if (std::holds_alternative<sn::Slot>(f) && std::abs(width_minus_cutter) < 0.01) return sn::CenterMilling{};
  return sn::ContourParallel{};
}

MillingOutput mill_hole(PartModel& part, const MillingInput& in, const Options& o, std::vector<std::string>& warnings,
                        const sn::Two5DMillingOperation& op, const material_check::CutterShape& cutter, const LoopSense& sense,
                        double stepover, double axial, double allowance_side, double floor) {
  const auto& f = *in.feature;
  const double hole = *f.region.hole_radius, r = cutter.radius;
  const Point2 c = f.region.frame.origin;
  if (r >= hole - 1e-6) {
    fail(o, in, "the cutter (diameter " + std::to_string(2 * r) + " mm) does not fit hole '" + f.region.id + "' (diameter " +
                    std::to_string(2 * hole) + " mm): mill it with a smaller cutter, or drill it");
  }
  if (f.region.cone_tip_angle) warnings.push_back(in.workingstep + ": a milled hole gets a flat bottom, not a drill point");
  const double outer = hole - r - allowance_side;
  if (outer <= 1e-6) fail(o, in, "the side allowance leaves no room for the cutter in hole '" + f.region.id + "'");
  // Radii from the inside out: the innermost passes over the middle, each the next stepover on.
  std::vector<double> radii;
  if (outer <= r) {
    radii.push_back(outer);
  } else {
    const double inner = r / 2, step = std::min(stepover, 1.8 * r);
    const int n = static_cast<int>(std::ceil((outer - inner) / step - 1e-9)) + 1;
    for (int k = 0; k < n; ++k) radii.push_back(inner + (outer - inner) * k / (n - 1));
  }
  const bool ccw = counter_clockwise_for(sense, false);
  const double turn = ccw ? 2 * kPi : -2 * kPi;
  const double slope = std::tan(o.ramp_angle_deg * kPi / 180);
  const double top = f.region.top_z;
  MotionBuilder b(part, PolygonSet{}, r, in.safe_z, o);
  auto turns_for = [&](double radius, double drop) {
    double pitch = 2 * kPi * radius * slope;
    if (op.axial_cutting_depth && *op.axial_cutting_depth > 0) pitch = std::min(pitch, *op.axial_cutting_depth);
    return std::max(1, static_cast<int>(std::ceil(drop / pitch - 1e-9)));
  };
  const bool by_levels = op.its_machining_strategy && !std::holds_alternative<sn::ContourSpiral>(*op.its_machining_strategy);
  if (op.its_machining_strategy && !std::holds_alternative<sn::ContourParallel>(*op.its_machining_strategy)) {
    warnings.push_back(in.workingstep + ": a round hole is milled by circles per level (CONTOUR_PARALLEL), not by the strategy given");
  }
  if (!by_levels) {
    // Helical milling: per radius a helix in whole turns from the top to the bottom, a circle
    // there, out.
    for (double rho : radii) {
      const Point2 s{c.x + rho, c.y};
      b.approach(s, top + 0.5, top + 0.5, nullptr);
      b.helix_to(c, floor, turn, turns_for(rho, top + 0.5 - floor));
      b.helix_to(c, floor, turn, 1);
      b.retract();
    }
  } else {
    // Circles per level: a helix at the innermost radius down to the level, then a circle at
    // each radius.
    double above = top;
    for (double z : levels(top, floor, axial)) {
      const Point2 s{c.x + radii.front(), c.y};
      if (!b.started()) {
        b.approach(s, above, above, nullptr);
      } else {
        b.feed_to({s.x, s.y, above});
      }
      b.helix_to(c, z, turn, turns_for(radii.front(), above - z));
      for (std::size_t k = 0; k < radii.size(); ++k) {
        if (k > 0) b.feed_to({c.x + radii[k], c.y, z});
        b.helix_to(c, z, turn, 1);
      }
      above = z;
    }
  }
  const PolygonSet disk = PolygonSet::from_curves({material_check::circle(c, radii.back() + r)}, kArcTolerance);
  part.record_cut(disk, floor);
  return {b.take(), floor};
}

}  // namespace

constexpr double kMaxPassesPerWorkingstep = 50000;

MillingOutput mill(PartModel& part, const MillingInput& in, const Options& o, std::vector<std::string>& warnings) {
  const auto& f = *in.feature;
  const auto& op = milling_of(*in.operation);
  const material_check::CutterShape cutter = material_check::cutter_of(*in.tool);
  const double r = cutter.radius, diameter = 2 * r;
  if (cutter.kind == material_check::CutterShape::Kind::Cone) {
    fail(o, in, "a " + std::string(in.tool->its_id) + " (a pointed tool) cannot mill; give an end mill");
  }
  const bool rough = roughing(*in.operation);
  const double allowance_side = rough && cuts_side(*in.operation) ? op.allowance_side.value_or(0) : 0;
  const double allowance_bottom = rough && cuts_bottom(*in.operation) ? op.allowance_bottom.value_or(0) : 0;
  if (allowance_side < 0 || allowance_bottom < 0) fail(o, in, "negative allowances make no sense");
  double floor = f.region.floor_z - (f.region.through ? o.breakthrough : 0) + allowance_bottom;
  const double top = f.region.top_z;
  if (floor >= top - 1e-9) fail(o, in, "the bottom allowance leaves nothing of feature '" + f.region.id + "' to cut");

  // Strategy and its parameters.
  double width_minus_cutter = 0;
  const auto* slot = std::get_if<sn::Slot>(in.cc2_feature);
  if (slot) {
    if (const auto* w = std::get_if<sn::LinearProfile>(&slot->swept_shape)) width_minus_cutter = w->profile_length - diameter;
  }
  const bool given = op.its_machining_strategy.has_value();
  const sn::Two5DMillingStrategy strategy = given ? *op.its_machining_strategy : default_strategy(*in.cc2_feature, width_minus_cutter);
  if (!given) warnings.push_back(in.workingstep + ": no machining strategy given; generated with the default for its feature (docs/toolpaths.md)");
  double stepover = o.stepover_ratio * diameter;
  if (const auto ov = overlap_of(strategy)) {
    if (!(*ov >= 0 && *ov < 1)) fail(o, in, "the strategy's overlap must be a ratio in [0, 1)");
    stepover = (1 - *ov) * diameter;
  }
  if (op.radial_cutting_depth) {
    if (!(*op.radial_cutting_depth > 0) || *op.radial_cutting_depth > diameter + 1e-9) {
      fail(o, in, "radial_cutting_depth must be positive and at most the cutter's diameter");
    }
    stepover = *op.radial_cutting_depth;
  }
  double axial = o.axial_depth_ratio * diameter;
  if (op.axial_cutting_depth) {
    if (!(*op.axial_cutting_depth > 0)) fail(o, in, "axial_cutting_depth must be positive");
    axial = *op.axial_cutting_depth;
  }
  // A bound on one workingstep's work, whatever the file says (a 0.01 mm step over a metre is
  // a hundred thousand passes a level): refused, naming the numbers that make it so.
  const double extent = std::max(f.box.xmax - f.box.xmin, f.box.ymax - f.box.ymin);
  const double passes = std::ceil(extent / stepover) + 1, layers = std::ceil((top - floor) / axial);
  if (!(passes * layers <= kMaxPassesPerWorkingstep)) {
    fail(o, in, "feature '" + f.region.id + "' would need about " + std::to_string(static_cast<long long>(std::min(passes, 1e15))) +
                    " passes a level on " + std::to_string(static_cast<long long>(std::min(layers, 1e15))) +
                    " levels, more than the generator's bound of " + std::to_string(static_cast<long long>(kMaxPassesPerWorkingstep)) +
                    " passes: give a larger stepover (overlap, radial_cutting_depth) or axial_cutting_depth");
  }
  LoopSense sense;
  if (in.technology->spindle && *in.technology->spindle > 0) sense.spindle_clockwise = false;
  std::visit(
      [&](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, sn::ContourParallel> || std::is_same_v<S, sn::ContourSpiral>) {
          if (s.rotation_direction) sense.counter_clockwise = *s.rotation_direction == sn::RotDirection::Ccw;
          if (s.cutmode) sense.climb = *s.cutmode == sn::CutmodeType::Climb;
        } else if constexpr (std::is_same_v<S, sn::Unidirectional>) {
          if (s.cutmode) sense.climb = *s.cutmode == sn::CutmodeType::Climb;
        } else if constexpr (std::is_same_v<S, sn::BidirectionalContour> || std::is_same_v<S, sn::ContourBidirectional>) {
          if (s.rotation_direction) sense.counter_clockwise = *s.rotation_direction == sn::RotDirection::Ccw;
          if (s.spiral_cutmode) sense.climb = *s.spiral_cutmode == sn::CutmodeType::Climb;
        }
      },
      strategy);

  if (f.region.hole_radius) {
    return mill_hole(part, in, o, warnings, op, cutter, sense, stepover, axial, allowance_side, floor);
  }

  // A closed feature must hold the cutter (and its allowance) somewhere: else nothing of it can
  // be cut to size (and a cutter reaching in from outside the stock would cut nothing).
  const bool closed_feature = std::holds_alternative<sn::ClosedPocket>(*in.cc2_feature) || (slot && f.region.open_edges.empty());
  if (closed_feature && !(slot && std::abs(width_minus_cutter) <= 0.01) &&
      f.area.offset(-(r + allowance_side - 1e-4), kArcTolerance).empty()) {
    fail(o, in, "the cutter (diameter " + std::to_string(diameter) + " mm) does not fit feature '" + f.region.id + "'");
  }
  const ClearingArea area = clearing_area(part, f, floor, r, allowance_side, o.run_out);
  const bool centre_line = std::holds_alternative<sn::CenterMilling>(strategy) && slot && std::abs(width_minus_cutter) <= 0.01;
  if ((area.centres.empty() || area.area.intersected(area.centres.offset(r, kArcTolerance)).empty()) && !centre_line) {
    fail(o, in, "the cutter (diameter " + std::to_string(diameter) + " mm) does not fit feature '" + f.region.id + "'");
  }
  const material_check::Box2 near = grown(f.box, 2 * diameter + o.run_out);
  // A slot as wide as the cutter has no area for its axis, only its centre line.
  PolygonSet axis_area = area.centres;
  PlanarCurve course;
  if (centre_line) {
    const double angle = direction_angle(f.region.frame, slot->course_of_travel.its_direction);
    const Point2 u{std::cos(angle), std::sin(angle)}, a = f.region.frame.origin;
    const double len = slot->course_of_travel.distance.theoretical_size, out = r + o.run_out;
    course.segments.emplace_back(LineSegment{{a.x - u.x * out, a.y - u.y * out}, {a.x + u.x * (len + out), a.y + u.y * (len + out)}});
    axis_area = swept_by({course}, 0.01);
  }
  MotionBuilder b(part, axis_area, r, in.safe_z, o);
  double above = top;
  std::vector<std::pair<PolygonSet, double>> cut_areas;
  int index = 0;
  for (double z : levels(top, floor, axial)) {
    const PolygonSet left = centre_line ? without_slivers(f.area.minus(part.cleared_at(z, near)), 0.004)
                                        : to_cut(area, part.cleared_at(z, near));
    if (left.empty()) {
      above = z;
      continue;
    }
    std::vector<Cut> cuts;
    if (std::holds_alternative<sn::CenterMilling>(strategy) && !slot) {
      // A face (or step) no wider than the cutter: one pass along its course through the middle
      // of what is left, in and out past its ends.
      double angle = f.region.frame.angle;
      if (const auto* face = std::get_if<sn::PlanarFace>(in.cc2_feature)) angle = direction_angle(f.region.frame, face->course_of_travel.its_direction);
      const Point2 u{std::cos(angle), std::sin(angle)}, v{-u.y, u.x};
      double lo = 1e300, hi = -1e300, across_lo = 1e300, across_hi = -1e300;
      for (const auto& ring : left.rings()) {
        for (const auto& q : ring) {
          const double along = q.x * u.x + q.y * u.y, across = q.x * v.x + q.y * v.y;
          lo = std::min(lo, along), hi = std::max(hi, along);
          across_lo = std::min(across_lo, across), across_hi = std::max(across_hi, across);
        }
      }
      if (across_hi - across_lo > diameter + 0.01) {
        // Wider than one pass (the recogniser also calls a face cut by one loop around its
        // middle CENTER_MILLING): passes along its course, said in a warning.
        if (index == 0) {
          warnings.push_back(in.workingstep + ": CENTER_MILLING makes one pass, and feature '" + f.region.id + "' is " +
                             std::to_string(across_hi - across_lo) + " mm wide across its course for a " + std::to_string(diameter) +
                             " mm cutter: milled by passes along its course (BIDIRECTIONAL)");
        }
        cuts = parallel_cuts(area, left, angle, stepover, true, true, sense);
      } else {
        const double mid = (across_lo + across_hi) / 2, out = r + o.run_out;
        auto at = [&](double along) { return Point2{u.x * along + v.x * mid, u.y * along + v.y * mid}; };
        PlanarCurve line;
        line.segments.emplace_back(LineSegment{at(lo - out), at(hi + out)});
        if (index % 2) line = line.reversed();
        cuts.push_back({std::move(line), false});
      }
    } else if (std::holds_alternative<sn::CenterMilling>(strategy)) {
      if (width_minus_cutter < -0.01) fail(o, in, "the cutter is wider than slot '" + f.region.id + "'");
      const auto& d = slot->course_of_travel.its_direction;
      const double angle = direction_angle(f.region.frame, d);
      if (width_minus_cutter > 0.01) {
        // A slot wider than the cutter: passes along its course across its width.
        cuts = parallel_cuts(area, left, angle, std::min(stepover, width_minus_cutter), true, true, sense);
      } else {
        // The centre line, past open ends until the cutter is out; back and forth level by level.
        const Point2 u{std::cos(angle), std::sin(angle)};
        const Point2 a = f.region.frame.origin;
        const double len = slot->course_of_travel.distance.theoretical_size;
        auto open_end = [&](std::size_t k) { return k < slot->end_conditions.size() && slot->end_conditions[k] == sn::SlotEndType::Open; };
        const double before = open_end(0) ? r + o.run_out : 0, after = open_end(1) ? r + o.run_out : 0;
        PlanarCurve line;
        line.segments.emplace_back(LineSegment{{a.x - u.x * before, a.y - u.y * before}, {a.x + u.x * (len + after), a.y + u.y * (len + after)}});
        if (index % 2) line = line.reversed();
        cuts.push_back({std::move(line), false});
      }
    } else if (const auto* bi = std::get_if<sn::Bidirectional>(&strategy)) {
      double angle = f.region.frame.angle;
      if (bi->feed_direction) angle = direction_angle(f.region.frame, *bi->feed_direction);
      else if (const auto* face = std::get_if<sn::PlanarFace>(in.cc2_feature)) angle = direction_angle(f.region.frame, face->course_of_travel.its_direction);
      const bool left_side = bi->stepover_direction.value_or(sn::LeftOrRight::Left) == sn::LeftOrRight::Left;
      cuts = parallel_cuts(area, left, angle, stepover, left_side, true, sense);
    } else if (std::holds_alternative<sn::BidirectionalContour>(strategy) ||
               std::holds_alternative<sn::ContourBidirectional>(strategy)) {
      // Passes back and forth and the contour along the boundary: after them
      // (BIDIRECTIONAL_CONTOUR, as parallel_cuts ends), or before them (CONTOUR_BIDIRECTIONAL).
      const bool contour_first = std::holds_alternative<sn::ContourBidirectional>(strategy);
      const auto feed = contour_first ? std::get<sn::ContourBidirectional>(strategy).feed_direction
                                      : std::get<sn::BidirectionalContour>(strategy).feed_direction;
      const auto side = contour_first ? std::get<sn::ContourBidirectional>(strategy).stepover_direction
                                      : std::get<sn::BidirectionalContour>(strategy).stepover_direction;
      double angle = f.region.frame.angle;
      if (feed) angle = direction_angle(f.region.frame, *feed);
      cuts = parallel_cuts(area, left, angle, stepover, side.value_or(sn::LeftOrRight::Left) == sn::LeftOrRight::Left, true, sense);
      if (contour_first) {
        const auto loops = std::find_if(cuts.rbegin(), cuts.rend(), [](const Cut& c) { return !c.path.closed; }).base();
        std::rotate(cuts.begin(), loops, cuts.end());
      }
    } else if (const auto* uni = std::get_if<sn::Unidirectional>(&strategy)) {
      double angle = f.region.frame.angle;
      if (uni->feed_direction) angle = direction_angle(f.region.frame, *uni->feed_direction);
      else if (const auto* face = std::get_if<sn::PlanarFace>(in.cc2_feature)) angle = direction_angle(f.region.frame, face->course_of_travel.its_direction);
      cuts = parallel_cuts(area, left, angle, stepover, true, false, sense);
    } else if (std::holds_alternative<sn::ContourSpiral>(strategy)) {
      cuts = spiral_cuts(area, left, std::min(stepover, diameter), sense);
    } else {
      bool outward = !area.open;
      if (o.contour_order == ContourOrder::Inward) outward = false;
      if (o.contour_order == ContourOrder::Outward) outward = true;
      cuts = contour_parallel_cuts(area, left, std::min(stepover, diameter), outward, sense);
    }
    if (cuts.empty()) {
      above = z;
      continue;
    }
    b.level(z, above, cuts);
    std::vector<PlanarCurve> paths;
    for (const auto& cut : cuts) paths.push_back(cut.path);
    cut_areas.emplace_back(swept_by(paths, r), z);
    above = z;
    ++index;
  }
  if (!b.started()) {
    warnings.push_back(in.workingstep + ": nothing left to cut (earlier workingsteps removed it all)");
    return {};
  }
  for (const auto& [a, z] : cut_areas) part.record_cut(a, z);
  return {b.take(), floor};
}

}  // namespace ncbridge::toolpath_generator
