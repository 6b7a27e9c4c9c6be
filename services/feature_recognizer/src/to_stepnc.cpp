#include "ncbridge/feature_recognizer/to_stepnc.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <type_traits>
#include <utility>

#include "to_stepnc_strategy.hpp"

namespace ncbridge::feature_recognizer {
namespace {

namespace sn = stepnc;
constexpr double kPi = 3.14159265358979323846;
// G-code carries no tolerances: every toleranced length gets the CC1 holes' +/-0.1 mm.
constexpr double kTolerance = 0.1;
// Feature geometry comes from polygon fits: keep it to 1e-6 mm so files show 70. not 69.9999999.
double tidy(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0 ? 0 : r;  // no -0.
}

sn::TolerancedLengthMeasure toleranced(double size) {
  return {std::max(tidy(size), 1e-3), kTolerance, kTolerance, 3};
}

sn::Direction planar_direction(double angle_deg) {
  const double a = angle_deg * kPi / 180;
  return {tidy(std::cos(a)), tidy(std::sin(a)), 0};
}

// A feature frame: origin at (x, y, z), local x along `x_axis` (in the XY plane), z up.
struct Frame {
  double x = 0, y = 0, z = 0;
  sn::Direction x_axis{1, 0, 0};

  sn::Axis2Placement3d placement() const { return {{tidy(x), tidy(y), tidy(z)}, {0, 0, 1}, x_axis}; }
  sn::CartesianPoint local(double px, double py, double pz) const {
    const double dx = px - x, dy = py - y;
    return {tidy(dx * x_axis.x + dy * x_axis.y), tidy(-dx * x_axis.y + dy * x_axis.x), tidy(pz - z)};
  }
  sn::Direction local_direction(const sn::Direction& d) const {
    return {tidy(d.x * x_axis.x + d.y * x_axis.y), tidy(-d.x * x_axis.y + d.y * x_axis.x), tidy(d.z)};
  }
};

sn::Plane depth_plane(double depth) { return {{{0, 0, -tidy(depth)}, {0, 0, 1}, {1, 0, 0}}}; }

// A closed outline (first point not repeated) as a closed polyline in the frame, at z = 0.
sn::CompositeCurve closed_polyline(const std::vector<Point2>& ring, const Frame& f) {
  sn::Polyline line;
  for (const auto& p : ring) line.points.push_back(f.local(p.x, p.y, f.z));
  if (!ring.empty()) line.points.push_back(f.local(ring.front().x, ring.front().y, f.z));
  return {{line}};
}

std::vector<Point2> rectangle_ring(const RecognizedFeature& r) {
  const sn::Direction d = planar_direction(r.profile.angle_deg);
  const double hl = r.profile.length / 2, hw = r.profile.width / 2;
  std::vector<Point2> ring;
  for (const auto& [s, t] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
    ring.push_back({r.x + s * hl * d.x - t * hw * d.y, r.y + s * hl * d.y + t * hw * d.x});
  }
  return ring;
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

// ---- features

sn::Feature round_hole(const RecognizedFeature& r, const std::string& id) {
  sn::RoundHole h;
  h.its_id = id;
  h.feature_placement = Frame{r.x, r.y, r.top_z}.placement();
  h.depth = depth_plane(r.depth());
  h.diameter = toleranced(r.diameter);
  switch (r.bottom) {
    case BottomCondition::Through: h.bottom_condition = sn::ThroughBottomCondition{}; break;
    case BottomCondition::Conical: h.bottom_condition = sn::ConicalHoleBottom{tidy(r.bottom_angle_deg)}; break;
    default: h.bottom_condition = sn::FlatHoleBottom{}; break;
  }
  return h;
}

// The face's frame is at the corner where its passes start: local x across the passes (the
// removal boundary, `width` long), local y along them (the course of travel, `length`), as in
// ISO 14649-11 example 1 and the paper's appendix A.2.
sn::Feature planar_face(const RecognizedFeature& r, const std::string& id) {
  const sn::Direction along = planar_direction(r.profile.angle_deg);
  const sn::Direction across{tidy(along.y), tidy(-along.x), 0};
  Frame f{r.x - r.profile.width / 2 * across.x - r.profile.length / 2 * along.x,
          r.y - r.profile.width / 2 * across.y - r.profile.length / 2 * along.y, r.top_z, across};
  sn::PlanarFace p;
  p.its_id = id;
  p.feature_placement = f.placement();
  p.depth = depth_plane(r.depth());
  p.course_of_travel.distance = toleranced(r.profile.length);
  p.course_of_travel.its_direction = {0, 1, 0};
  p.removal_boundary.profile_length = tidy(r.profile.width);
  return p;
}

sn::ClosedProfile closed_profile(const RecognizedFeature& r, const Frame& f) {
  switch (r.profile.shape) {
    case ProfileShape::Rectangular:
      return sn::RectangularClosedProfile{std::nullopt, toleranced(r.profile.width), toleranced(r.profile.length)};
    case ProfileShape::Circular:
      return sn::CircularClosedProfile{std::nullopt, toleranced(r.profile.diameter)};
    default:
      return sn::GeneralClosedProfile{std::nullopt, closed_polyline(r.profile.outline, f)};
  }
}

sn::Feature closed_pocket(const RecognizedFeature& r, const std::string& id) {
  const Frame f{r.x, r.y, r.top_z, planar_direction(r.profile.angle_deg)};
  sn::ClosedPocket p;
  p.its_id = id;
  p.feature_placement = f.placement();
  p.depth = depth_plane(r.depth());
  if (r.bottom == BottomCondition::Through) p.bottom_condition = sn::ThroughPocketBottomCondition{};
  if (r.profile.shape == ProfileShape::Rectangular && r.profile.corner_radius > 0.01) {
    p.orthogonal_radius = toleranced(r.profile.corner_radius);  // the wall corners, about Z
  }
  p.feature_boundary = closed_profile(r, f);
  return p;
}

// Splits a closed outline into the run of edges lying on the part's open sides (the edges on
// the outline's bounding box at those sides) and the rest (the walls), each as an open polyline.
std::pair<std::vector<Point2>, std::vector<Point2>> open_and_wall_runs(const std::vector<Point2>& ring,
                                                                       const std::vector<OpenSide>& sides) {
  if (ring.size() < 3) return {ring, {}};
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const auto& p : ring) {
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x), ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  }
  constexpr double eps = 1e-3;
  auto on_open_side = [&](const Point2& a, const Point2& b) {
    for (auto s : sides) {
      if (s == OpenSide::XMinus && std::abs(a.x - xmin) < eps && std::abs(b.x - xmin) < eps) return true;
      if (s == OpenSide::XPlus && std::abs(a.x - xmax) < eps && std::abs(b.x - xmax) < eps) return true;
      if (s == OpenSide::YMinus && std::abs(a.y - ymin) < eps && std::abs(b.y - ymin) < eps) return true;
      if (s == OpenSide::YPlus && std::abs(a.y - ymax) < eps && std::abs(b.y - ymax) < eps) return true;
    }
    return false;
  };
  const std::size_t n = ring.size();
  std::vector<bool> open(n);
  for (std::size_t i = 0; i < n; ++i) open[i] = on_open_side(ring[i], ring[(i + 1) % n]);
  // The longest run of open edges (cyclically).
  std::size_t best_start = 0, best_len = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!open[i] || open[(i + n - 1) % n]) continue;
    std::size_t len = 0;
    while (len < n && open[(i + len) % n]) ++len;
    if (len > best_len) best_len = len, best_start = i;
  }
  if (best_len == 0 || best_len == n) return {ring, {}};
  std::vector<Point2> open_run, wall_run;
  for (std::size_t k = 0; k <= best_len; ++k) open_run.push_back(ring[(best_start + k) % n]);
  for (std::size_t k = best_len; k <= n; ++k) wall_run.push_back(ring[(best_start + k) % n]);
  return {open_run, wall_run};
}

sn::OpenProfile general_profile(const std::vector<Point2>& points, const Frame& f) {
  sn::Polyline line;
  for (const auto& p : points) line.points.push_back(f.local(p.x, p.y, f.z));
  return sn::GeneralProfile{std::nullopt, {{line}}};
}

sn::Feature open_pocket(const RecognizedFeature& r, const std::string& id) {
  const Frame f{r.x, r.y, r.top_z, planar_direction(r.profile.angle_deg)};
  sn::OpenPocket p;
  p.its_id = id;
  p.feature_placement = f.placement();
  p.depth = depth_plane(r.depth());
  if (r.bottom == BottomCondition::Through) p.bottom_condition = sn::ThroughPocketBottomCondition{};
  const auto [open_run, wall_run] = open_and_wall_runs(r.profile.outline, r.open_sides);
  if (open_run.size() >= 2) {
    p.open_boundary = general_profile(open_run, f);
  } else {
    p.open_boundary = sn::LinearProfile{std::nullopt, tidy(r.profile.length)};
  }
  if (wall_run.size() >= 2) p.wall_boundary = general_profile(wall_run, f);
  return p;
}

// The slot's frame is at the start of its centre line, local x along it.
sn::Feature slot(const RecognizedFeature& r, const std::string& id) {
  Point2 a{r.x, r.y}, b{r.x, r.y};
  if (r.slot_course.size() >= 2) a = r.slot_course.front(), b = r.slot_course.back();
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  const sn::Direction along = length > 1e-9 ? sn::Direction{tidy((b.x - a.x) / length), tidy((b.y - a.y) / length), 0}
                                            : planar_direction(r.profile.angle_deg);
  sn::Slot s;
  s.its_id = id;
  s.feature_placement = Frame{a.x, a.y, r.top_z, along}.placement();
  s.depth = depth_plane(r.depth());
  s.course_of_travel.distance = toleranced(length);
  s.course_of_travel.its_direction = {1, 0, 0};
  s.swept_shape = sn::LinearProfile{std::nullopt, tidy(r.slot_width)};  // the floor across the slot
  for (auto e : r.slot_ends) {
    s.end_conditions.push_back(e == SlotEnd::Radiused ? sn::SlotEndType::Radiused
                               : e == SlotEnd::Flat   ? sn::SlotEndType::Flat
                                                      : sn::SlotEndType::Open);
  }
  return s;
}

// ISO 14649-10 sweeps a step's wall along its open_boundary and the step runs from that wall
// out to the workpiece's edge: the frame is at one end of the wall's foot, local x along the
// wall, local y away from it towards the open side. So the file says where the wall stands
// (the step's width), not only how long the step is.
sn::Feature step(const RecognizedFeature& r, const std::string& id) {
  double xmin = r.x, xmax = r.x, ymin = r.y, ymax = r.y;
  if (!r.profile.outline.empty()) {
    xmin = ymin = 1e300, xmax = ymax = -1e300;
    for (const auto& p : r.profile.outline) {
      xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x), ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
    }
  }
  // The open side the step runs along: the one parallel to its longer extent.
  const bool runs_along_y = (ymax - ymin) >= (xmax - xmin);
  OpenSide side = runs_along_y ? OpenSide::XMinus : OpenSide::YMinus;
  for (auto s : r.open_sides) {
    const bool along_y = s == OpenSide::XMinus || s == OpenSide::XPlus;
    if (along_y == runs_along_y) {
      side = s;
      break;
    }
  }
  double nx = 0, ny = 0, wx = 0, wy = 0;  // inward normal (from the open side), middle of the wall
  const double cx = (xmin + xmax) / 2, cy = (ymin + ymax) / 2;
  switch (side) {
    case OpenSide::XMinus: nx = 1, wx = xmax, wy = cy; break;
    case OpenSide::XPlus: nx = -1, wx = xmin, wy = cy; break;
    case OpenSide::YMinus: ny = 1, wx = cx, wy = ymax; break;
    case OpenSide::YPlus: ny = -1, wx = cx, wy = ymin; break;
  }
  const sn::Direction along{-ny, nx, 0};  // so that local y (z x along) points out, -n
  const double length = runs_along_y ? ymax - ymin : xmax - xmin;
  sn::Step s;
  s.its_id = id;
  s.feature_placement = Frame{wx - length / 2 * along.x, wy - length / 2 * along.y, r.top_z, along}.placement();
  s.depth = depth_plane(r.depth());
  s.open_boundary.distance = toleranced(length);
  s.open_boundary.its_direction = {1, 0, 0};
  return s;
}

sn::Feature outside_profile(const RecognizedFeature& r, const std::string& id) {
  const Frame f{r.x, r.y, r.top_z, {1, 0, 0}};
  sn::GeneralOutsideProfile p;
  p.its_id = id;
  p.feature_placement = f.placement();
  p.depth = depth_plane(r.depth());
  p.profile_swept_shape.distance = toleranced(r.depth());
  p.profile_swept_shape.its_direction = {0, 0, -1};
  p.feature_boundary = closed_polyline(r.profile.outline.empty() ? rectangle_ring(r) : r.profile.outline, f);
  p.closed = true;
  return p;
}

sn::Feature region(const RecognizedFeature& r, const std::string& id) {
  const Frame f{r.x, r.y, r.top_z, {1, 0, 0}};
  sn::Region g;
  g.its_id = id;
  g.feature_placement = f.placement();
  g.proj_curve = closed_polyline(r.profile.outline.empty() ? rectangle_ring(r) : r.profile.outline, f);
  g.proj_dir = {0, 0, -1};
  g.depth = toleranced(r.depth());
  return g;
}

sn::Feature feature_of(const RecognizedFeature& r, const std::string& id) {
  switch (r.type) {
    case FeatureType::PlanarFace: return planar_face(r, id);
    case FeatureType::RoundHole: return round_hole(r, id);
    case FeatureType::ClosedPocket: return closed_pocket(r, id);
    case FeatureType::OpenPocket: return open_pocket(r, id);
    case FeatureType::Slot: return slot(r, id);
    case FeatureType::Step: return step(r, id);
    case FeatureType::GeneralOutsideProfile: return outside_profile(r, id);
    case FeatureType::Region: break;
  }
  return region(r, id);
}

// The frame strategies' directions are given in (the feature placement's).
Frame frame_of(const sn::Feature& f) {
  return std::visit(
      [](const auto& x) {
        using F = std::decay_t<decltype(x)>;
        sn::Axis2Placement3d a;
        if constexpr (std::is_same_v<F, sn::Region>) {
          if (x.feature_placement) a = *x.feature_placement;
        } else {
          a = x.feature_placement;
        }
        return Frame{a.location.x, a.location.y, a.location.z, a.ref_direction};
      },
      f);
}

// ---- operations

const char* operation_word(OperationType t) {
  switch (t) {
    case OperationType::PlaneRoughMilling:
    case OperationType::SideRoughMilling:
    case OperationType::BottomAndSideRoughMilling: return "ROUGH";
    case OperationType::PlaneFinishMilling:
    case OperationType::SideFinishMilling:
    case OperationType::BottomAndSideFinishMilling: return "FINISH";
    case OperationType::Drilling: return "DRILL";
    case OperationType::MultistepDrilling: return "PECK DRILL";
    case OperationType::CenterDrilling: return "CENTER DRILL";
    case OperationType::Reaming: return "REAM";
    case OperationType::BoringOperation: return "BORE";
    case OperationType::Tapping: return "TAP";
    case OperationType::FreeformOperation: break;
  }
  return "MILL";
}

std::optional<sn::Two5DMillingStrategy> strategy_of(const RecognizedOperation& op, const PathDirections& d,
                                                    const Frame& frame, bool spindle_clockwise, bool outside) {
  // Climb milling: the cutter's rotation and its travel along the wall agree. With a clockwise
  // (M3) spindle a pocket's contour run clockwise is conventional, counter-clockwise climb; an
  // outside profile the other way round.
  auto cutmode = [&]() -> std::optional<sn::CutmodeType> {
    if (!d.rotation) return std::nullopt;
    const bool ccw = *d.rotation == sn::RotDirection::Ccw;
    const bool climb = (ccw != outside) == spindle_clockwise;
    return climb ? sn::CutmodeType::Climb : sn::CutmodeType::Conventional;
  };
  auto feed = [&]() -> std::optional<sn::Direction> {
    if (!d.feed_direction) return std::nullopt;
    return frame.local_direction(*d.feed_direction);
  };
  switch (op.strategy) {
    case Strategy::Unidirectional: return sn::Unidirectional{feed(), std::nullopt};
    case Strategy::Bidirectional: return sn::Bidirectional{feed(), d.stepover_direction};
    case Strategy::CenterMilling: return sn::CenterMilling{};
    case Strategy::Contour:
    case Strategy::ContourParallel: return sn::ContourParallel{d.rotation, cutmode()};
    case Strategy::ContourSpiral: return sn::ContourSpiral{d.rotation, cutmode()};
    default: return std::nullopt;  // adaptive, helical, plunge: the explicit toolpath says it
  }
}

template <class Op>
Op two5d(const RecognizedOperation& r, bool first, double feature_depth, bool rough, bool side, bool plane) {
  Op op;
  if (r.axial_depth > 0) op.axial_cutting_depth = tidy(r.axial_depth);
  else if (first && r.layers <= 1) op.axial_cutting_depth = tidy(feature_depth);
  if (side && r.radial_depth > 0) op.radial_cutting_depth = tidy(r.radial_depth);
  // Roughing must state what it leaves (ISO 14649-11 WR1/WR2), 0 when nothing.
  if (side && (rough || r.side_allowance > 0)) op.allowance_side = tidy(r.side_allowance);
  if (plane && (rough || r.bottom_allowance > 0)) op.allowance_bottom = tidy(r.bottom_allowance);
  return op;
}

sn::Operation operation_shell(const RecognizedOperation& r, bool first, double feature_depth) {
  switch (r.type) {
    case OperationType::PlaneRoughMilling: return two5d<sn::PlaneRoughMilling>(r, first, feature_depth, true, false, true);
    case OperationType::PlaneFinishMilling: return two5d<sn::PlaneFinishMilling>(r, first, feature_depth, false, false, true);
    case OperationType::SideRoughMilling: return two5d<sn::SideRoughMilling>(r, first, feature_depth, true, true, false);
    case OperationType::SideFinishMilling: return two5d<sn::SideFinishMilling>(r, first, feature_depth, false, true, false);
    case OperationType::BottomAndSideRoughMilling:
      return two5d<sn::BottomAndSideRoughMilling>(r, first, feature_depth, true, true, true);
    case OperationType::BottomAndSideFinishMilling:
      return two5d<sn::BottomAndSideFinishMilling>(r, first, feature_depth, false, true, true);
    case OperationType::Drilling: return sn::Drilling{};
    case OperationType::MultistepDrilling: return sn::MultistepDrilling{};
    case OperationType::CenterDrilling: return sn::CenterDrilling{};
    case OperationType::Reaming: return sn::Reaming{};
    case OperationType::BoringOperation: return sn::Boring{};
    case OperationType::Tapping: return sn::Tapping{};
    case OperationType::FreeformOperation: break;
  }
  return sn::FreeformOperation{};
}

const sn::DrillingTypeOperation* as_drilling(const sn::Operation& op) {
  return std::visit(
      [](const auto& o) -> const sn::DrillingTypeOperation* {
        if constexpr (std::is_base_of_v<sn::DrillingTypeOperation, std::decay_t<decltype(o)>>) return &o;
        else return nullptr;
      },
      op);
}

sn::DrillingTypeOperation* as_drilling(sn::Operation& op) {
  return const_cast<sn::DrillingTypeOperation*>(as_drilling(std::as_const(op)));
}

// Where a CC1 operation's z values are measured from: its feature's placement height.
double placement_z(const sn::Feature& f) { return frame_of(f).z; }

// One CC1 drilling workingstep: the hole's absolute top, bottom and retract height.
struct DrillPass {
  double x = 0, y = 0, bottom = 0, retract = 0;
  const sn::Operation* cc1 = nullptr;
  sn::TechnologyRef technology;
  sn::MachineFunctionsRef functions;
};

DrillPass drill_pass(const sn::Project& cc1, const sn::MachiningWorkingstep& ws) {
  DrillPass p;
  const auto& op = cc1.operation(ws.its_operation);
  const auto& mop = sn::machining_operation(op);
  p.cc1 = &op;
  p.technology = mop.its_technology;
  p.functions = mop.its_machine_functions;
  const auto& feature = cc1.feature(ws.its_feature);
  const Frame f = frame_of(feature);
  p.x = f.x, p.y = f.y;
  double depth = 0;
  if (const auto* h = std::get_if<sn::RoundHole>(&feature)) depth = -h->depth.position.location.z;
  const auto* d = as_drilling(op);
  p.bottom = f.z - (d && d->cutting_depth ? *d->cutting_depth : depth);
  p.retract = f.z + mop.retract_plane.value_or(0);
  return p;
}

// The CC2 workplan under construction.
class Cc2Builder {
 public:
  Cc2Builder(const sn::Project& cc1, const std::vector<RecognizedFeature>& features)
      : cc1_(cc1), features_(features), ids_(cc2_feature_ids(features)) {}

  Cc2Project build() {
    auto& p = out_.project;
    p.its_id = cc1_.its_id;
    p.main_workplan.its_id = cc1_.main_workplan.its_id;
    p.workpiece = cc1_.workpiece;
    p.rawpiece = cc1_.rawpiece;
    p.setup = cc1_.setup;
    p.tools = cc1_.tools;
    p.technologies = cc1_.technologies;
    p.machine_functions = cc1_.machine_functions;
    for (std::size_t i = 0; i < features_.size(); ++i) p.features.push_back(feature_of(features_[i], ids_[i]));
    claim_workingsteps();
    walk_workplan();
    finish_drilling();
    set_strategies();
    for (std::size_t i = 0; i < features_.size(); ++i) {
      for (std::size_t j = 0; j < features_[i].operations.size(); ++j) {
        if (!operation_index_.count({i, j})) {
          out_.warnings.push_back(ids_[i] + ": operation " + std::string(to_string(features_[i].operations[j].type)) +
                                  " has no workingstep of its own (its cuts belong to an earlier operation): not written");
        }
      }
    }
    out_.feature_ids = ids_;
    out_.workingstep_ids.resize(features_.size());
    for (std::size_t i = 0; i < features_.size(); ++i) {
      for (std::size_t j = 0; j < features_[i].operations.size(); ++j) {
        auto it = workingstep_index_.find({i, j});
        out_.workingstep_ids[i].push_back(
            it == workingstep_index_.end()
                ? std::string()
                : std::get<sn::MachiningWorkingstep>(out_.project.main_workplan.its_elements.at(it->second)).its_id);
      }
    }
    return std::move(out_);
  }

 private:
  using OpKey = std::pair<std::size_t, std::size_t>;  // (feature, operation)

  void claim_workingsteps() {
    for (const auto& e : cc1_.main_workplan.its_elements) {
      if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) machining_.push_back(ws);
    }
    owner_.assign(machining_.size(), std::nullopt);
    for (std::size_t i = 0; i < features_.size(); ++i) {
      for (std::size_t j = 0; j < features_[i].operations.size(); ++j) {
        for (auto k : features_[i].operations[j].workingsteps) {
          if (k < owner_.size() && !owner_[k]) owner_[k] = OpKey{i, j};
        }
      }
    }
  }

  void walk_workplan() {
    std::size_t k = 0;  // machining workingsteps seen so far
    const auto& elements = cc1_.main_workplan.its_elements;
    for (std::size_t e = 0; e < elements.size(); ++e) {
      if (const auto* rapid = std::get_if<sn::RapidMovement>(&elements[e])) {
        // Between two workingsteps of one operation a rapid is part of its toolpath.
        if (k > 0 && k < owner_.size() && owner_[k - 1] && owner_[k - 1] == owner_[k] && rapid->its_toolpath) {
          auto& list = toolpath_of(*owner_[k]);
          for (auto t : rapid->its_toolpath->its_list) {
            t.its_type = sn::ToolpathType::Connect;
            list.its_list.push_back(std::move(t));
          }
          extend_source(*owner_[k], rapid->source);
        } else {
          out_.project.main_workplan.its_elements.push_back(*rapid);
        }
        continue;
      }
      if (const auto* probing = std::get_if<sn::WorkpieceProbing>(&elements[e])) {
        out_.project.main_workplan.its_elements.push_back(*probing);  // kept as it is, in its place
        continue;
      }
      const auto& ws = *machining_[k];
      if (!owner_[k]) {
        keep_cc1_workingstep(ws);
      } else {
        add_to_operation(*owner_[k], ws);
      }
      ++k;
    }
  }

  void keep_cc1_workingstep(const sn::MachiningWorkingstep& ws) {
    auto& p = out_.project;
    auto it = kept_features_.find(ws.its_feature.index);
    if (it == kept_features_.end()) {
      p.features.push_back(cc1_.feature(ws.its_feature));
      it = kept_features_.emplace(ws.its_feature.index, sn::FeatureRef{static_cast<std::uint32_t>(p.features.size() - 1)}).first;
    }
    p.operations.push_back(cc1_.operation(ws.its_operation));
    sn::MachiningWorkingstep copy = ws;
    copy.its_feature = it->second;
    copy.its_operation = {static_cast<std::uint32_t>(p.operations.size() - 1)};
    p.main_workplan.its_elements.push_back(std::move(copy));
  }

  sn::ToolpathList& toolpath_of(const OpKey& key) {
    auto& op = sn::machining_operation(out_.project.operations.at(operation_index_.at(key)));
    if (!op.its_toolpath) op.its_toolpath.emplace();
    return *op.its_toolpath;
  }

  void extend_source(const OpKey& key, const sn::SourceLines& s) {
    if (s.first_line == 0) return;
    auto& ws = std::get<sn::MachiningWorkingstep>(out_.project.main_workplan.its_elements.at(workingstep_index_.at(key)));
    if (ws.source.first_line == 0) {
      ws.source = s;
      return;
    }
    ws.source.first_line = std::min(ws.source.first_line, s.first_line);
    ws.source.last_line = std::max(ws.source.last_line, s.last_line);
  }

  void add_to_operation(const OpKey& key, const sn::MachiningWorkingstep& ws) {
    const auto& cc1_op = cc1_.operation(ws.its_operation);
    const auto& cc1_mop = sn::machining_operation(cc1_op);
    const auto& r = features_[key.first];
    const auto& rop = r.operations[key.second];
    auto& p = out_.project;
    if (!operation_index_.count(key)) {
      sn::Operation op = operation_shell(rop, key.second == 0, r.depth());
      auto& mop = sn::machining_operation(op);
      mop.its_id = operation_id(key);
      mop.its_tool = cc1_mop.its_tool;
      mop.its_technology = cc1_mop.its_technology;
      mop.its_machine_functions = cc1_mop.its_machine_functions;
      mop.start_point = cc1_mop.start_point;
      const std::string workingstep_id = "WS " + mop.its_id;
      p.operations.push_back(std::move(op));
      operation_index_[key] = p.operations.size() - 1;
      sn::MachiningWorkingstep cc2;
      cc2.its_id = workingstep_id;
      cc2.its_secplane = ws.its_secplane;
      cc2.its_feature = {static_cast<std::uint32_t>(key.first)};
      cc2.its_operation = {static_cast<std::uint32_t>(p.operations.size() - 1)};
      cc2.source = ws.source;
      p.main_workplan.its_elements.push_back(std::move(cc2));
      workingstep_index_[key] = p.main_workplan.its_elements.size() - 1;
    } else {
      extend_source(key, ws.source);
    }
    auto& op = p.operations.at(operation_index_.at(key));
    auto& mop = sn::machining_operation(op);
    // The highest retract of the CC1 operations, above the CC2 feature's placement.
    const double cc1_retract = placement_z(cc1_.feature(ws.its_feature)) + cc1_mop.retract_plane.value_or(-1e300);
    if (cc1_mop.retract_plane) {
      const double above = tidy(cc1_retract - placement_z(p.features.at(key.first)));
      if (!mop.retract_plane || above > *mop.retract_plane) mop.retract_plane = above;
    }
    if (as_drilling(cc1_op) && std::holds_alternative<sn::RoundHole>(cc1_.feature(ws.its_feature))) {
      drill_passes_[key].push_back(drill_pass(cc1_, ws));
      return;
    }
    if (!cc1_mop.its_toolpath) return;
    auto& list = toolpath_of(key);
    for (auto t : cc1_mop.its_toolpath->its_list) {
      if (!t.its_technology && !(cc1_mop.its_technology == mop.its_technology)) t.its_technology = cc1_mop.its_technology;
      if (!t.its_machine_functions && !(cc1_mop.its_machine_functions == mop.its_machine_functions)) {
        t.its_machine_functions = cc1_mop.its_machine_functions;
      }
      list.its_list.push_back(std::move(t));
    }
  }

  std::string operation_id(const OpKey& key) {
    std::string id = std::string(operation_word(features_[key.first].operations[key.second].type)) + " " + ids_[key.first];
    const int n = ++operation_names_[id];
    return n == 1 ? id : id + " " + std::to_string(n);
  }

  // Drilling operations from canned cycles: one CC1 cycle keeps its parameters; several
  // (deeper and deeper passes of one tool) also get the explicit passes as a toolpath so the
  // intermediate depths are not lost.
  void finish_drilling() {
    for (auto& [key, passes] : drill_passes_) {
      auto& op = out_.project.operations.at(operation_index_.at(key));
      const double top = placement_z(out_.project.features.at(key.first));
      const DrillPass* deepest = &passes.front();
      for (const auto& pass : passes) {
        if (pass.bottom < deepest->bottom) deepest = &pass;
      }
      if (auto* d = as_drilling(op)) {
        const auto* from = as_drilling(*deepest->cc1);
        d->cutting_depth = tidy(top - deepest->bottom);
        if (from) {
          d->previous_diameter = from->previous_diameter;
          d->dwell_time_bottom = from->dwell_time_bottom;
          d->feed_on_retract = from->feed_on_retract;
          d->its_machining_strategy = from->its_machining_strategy;
        }
      }
      copy_drilling_details(op, *deepest->cc1, passes, top);
      if (passes.size() < 2) continue;
      auto& list = toolpath_of(key);
      for (const auto& pass : passes) {
        sn::CutterLocationTrajectory t;
        t.its_technology = pass.technology;
        t.its_machine_functions = pass.functions;
        t.basiccurve.segments.emplace_back(sn::Polyline{{{pass.x, pass.y, pass.retract}, {pass.x, pass.y, pass.bottom},
                                                         {pass.x, pass.y, pass.retract}}});
        list.its_list.push_back(std::move(t));
      }
    }
  }

  // Strategies need the operation's whole toolpath and the feature's frame: set last.
  void set_strategies() {
    for (const auto& [key, index] : operation_index_) {
      auto& op = out_.project.operations.at(index);
      auto* milling = std::visit(
          [](auto& o) -> sn::Two5DMillingOperation* {
            if constexpr (std::is_base_of_v<sn::Two5DMillingOperation, std::decay_t<decltype(o)>>) return &o;
            else return nullptr;
          },
          op);
      if (!milling) continue;
      std::vector<const sn::CompositeCurve*> cutting;
      if (milling->its_toolpath) {
        for (const auto& t : milling->its_toolpath->its_list) {
          if (t.its_type == sn::ToolpathType::TrajectoryPath || t.its_type == sn::ToolpathType::Contact) {
            cutting.push_back(&t.basiccurve);
          }
        }
      }
      const auto directions = analyse_path_directions(cutting);
      const auto& tech = out_.project.technology(milling->its_technology);
      const bool clockwise = tech.spindle.value_or(-1) <= 0;
      const auto& r = features_[key.first];
      milling->its_machining_strategy = strategy_of(r.operations[key.second], directions, frame_of(out_.project.features.at(key.first)),
                                                    clockwise, r.type == FeatureType::GeneralOutsideProfile);
    }
  }

  static void copy_drilling_details(sn::Operation& op, const sn::Operation& cc1, const std::vector<DrillPass>& passes,
                                    double top) {
    if (auto* m = std::get_if<sn::MultistepDrilling>(&op)) {
      if (const auto* c = std::get_if<sn::MultistepDrilling>(&cc1)) {
        m->retract_distance = c->retract_distance;
        m->first_depth = c->first_depth;
        m->depth_of_step = c->depth_of_step;
        m->dwell_time_step = c->dwell_time_step;
      } else {  // successive passes of one tool, each deeper: the steps between them
        double previous = top, step = 0;
        for (const auto& pass : passes) {
          step = std::max(step, previous - pass.bottom);
          previous = std::min(previous, pass.bottom);
        }
        m->first_depth = tidy(top - passes.front().bottom);
        m->depth_of_step = tidy(step);
        m->retract_distance = tidy(std::max(0.0, passes.front().retract - top));
      }
    } else if (auto* b = std::get_if<sn::Boring>(&op)) {
      if (const auto* c = std::get_if<sn::Boring>(&cc1)) {
        b->spindle_stop_at_bottom = c->spindle_stop_at_bottom;
        b->depth_of_testcut = c->depth_of_testcut;
        b->waiting_position = c->waiting_position;
      }
    } else if (auto* rm = std::get_if<sn::Reaming>(&op)) {
      if (const auto* c = std::get_if<sn::Reaming>(&cc1)) {
        rm->spindle_stop_at_bottom = c->spindle_stop_at_bottom;
        rm->depth_of_testcut = c->depth_of_testcut;
        rm->waiting_position = c->waiting_position;
      }
    } else if (auto* t = std::get_if<sn::Tapping>(&op)) {
      if (const auto* c = std::get_if<sn::Tapping>(&cc1)) t->compensation_chuck = c->compensation_chuck;
    }
  }

  const sn::Project& cc1_;
  const std::vector<RecognizedFeature>& features_;
  std::vector<std::string> ids_;
  Cc2Project out_;
  std::vector<const sn::MachiningWorkingstep*> machining_;
  std::vector<std::optional<OpKey>> owner_;
  std::map<OpKey, std::size_t> operation_index_, workingstep_index_;
  std::map<OpKey, std::vector<DrillPass>> drill_passes_;
  std::map<std::uint32_t, sn::FeatureRef> kept_features_;
  std::map<std::string, int> operation_names_;
};

}  // namespace

std::vector<std::string> cc2_feature_ids(const std::vector<RecognizedFeature>& features) {
  std::map<FeatureType, int> counts;
  std::vector<std::string> ids;
  for (const auto& f : features) {
    const int n = ++counts[f.type];
    const std::string number = std::to_string(n);
    switch (f.type) {
      case FeatureType::PlanarFace: ids.push_back("PLANAR FACE" + number); break;
      case FeatureType::RoundHole: ids.push_back("HOLE" + number + " D=" + number_text(f.diameter) + "MM"); break;
      case FeatureType::ClosedPocket: ids.push_back("POCKET" + number); break;
      case FeatureType::OpenPocket: ids.push_back("OPEN POCKET" + number); break;
      case FeatureType::Slot: ids.push_back("SLOT" + number); break;
      case FeatureType::Step: ids.push_back("STEP" + number); break;
      case FeatureType::GeneralOutsideProfile: ids.push_back("PROFILE" + number); break;
      case FeatureType::Region: ids.push_back("REGION" + number); break;
    }
  }
  return ids;
}

Cc2Project cc2_from_cc1(const stepnc::Project& cc1, const std::vector<RecognizedFeature>& features) {
  return Cc2Builder(cc1, features).build();
}

}  // namespace ncbridge::feature_recognizer
