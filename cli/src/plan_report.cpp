#include "plan_report.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

namespace ncbridge::cli {

namespace fr = feature_recognizer;
namespace pr = part_reader;
namespace sn = stepnc;

namespace {

double tidy(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0 ? 0 : r;
}

fr::FeatureType type_of(pr::FeatureKind kind) {
  switch (kind) {
    case pr::FeatureKind::PlanarFace: return fr::FeatureType::PlanarFace;
    case pr::FeatureKind::RoundHole: return fr::FeatureType::RoundHole;
    case pr::FeatureKind::ClosedPocket: return fr::FeatureType::ClosedPocket;
    case pr::FeatureKind::OpenPocket: return fr::FeatureType::OpenPocket;
    case pr::FeatureKind::Slot: return fr::FeatureType::Slot;
    case pr::FeatureKind::Step: return fr::FeatureType::Step;
    case pr::FeatureKind::GeneralOutsideProfile: return fr::FeatureType::GeneralOutsideProfile;
  }
  return fr::FeatureType::Region;
}

fr::OpenSide side_of(double dx, double dy) {
  if (std::abs(dx) >= std::abs(dy)) return dx > 0 ? fr::OpenSide::XPlus : fr::OpenSide::XMinus;
  return dy > 0 ? fr::OpenSide::YPlus : fr::OpenSide::YMinus;
}

// The feature's local frame in the setup's XY plane.
struct Frame {
  double ox, oy, cx, sx;
  fr::Point2 world(double x, double y) const { return {ox + x * cx - y * sx, oy + x * sx + y * cx}; }
};

Frame frame_of(const pr::Feature& f) {
  const auto& p = f.placement;
  const double n = std::hypot(p.ref_direction.x, p.ref_direction.y);
  return {p.location.x, p.location.y, n > 0 ? p.ref_direction.x / n : 1, n > 0 ? p.ref_direction.y / n : 0};
}

// A closed outline's corners with its arcs cut into chords of at most 10 degrees (the report and
// the page draw polygons).
std::vector<std::pair<double, double>> outline_points(const std::vector<pr::OutlineVertex>& outline) {
  std::vector<std::pair<double, double>> points;
  const std::size_t n = outline.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % n];
    points.emplace_back(a.x, a.y);
    if (a.bulge == 0) continue;
    const double chord = std::hypot(b.x - a.x, b.y - a.y);
    if (chord < 1e-12) continue;
    const double sweep = 4 * std::atan(a.bulge);
    const double d = chord * (1 - a.bulge * a.bulge) / (4 * a.bulge);
    const double cx = (a.x + b.x) / 2 - (b.y - a.y) / chord * d, cy = (a.y + b.y) / 2 + (b.x - a.x) / chord * d;
    const double r = std::hypot(a.x - cx, a.y - cy), start = std::atan2(a.y - cy, a.x - cx);
    const int k = std::max(2, static_cast<int>(std::ceil(std::abs(sweep) * 18 / std::numbers::pi)));
    for (int j = 1; j < k; ++j) points.emplace_back(cx + r * std::cos(start + sweep * j / k), cy + r * std::sin(start + sweep * j / k));
  }
  return points;
}

double angle_of(double cx, double sx) {
  double a = std::atan2(sx, cx) * 180 / std::numbers::pi;
  while (a < 0) a += 180;
  while (a >= 180 - 1e-9) a -= 180;
  return tidy(a);
}

fr::RecognizedFeature as_recognized(const pr::Feature& f) {
  fr::RecognizedFeature r;
  r.type = type_of(f.kind);
  r.x = f.placement.location.x;
  r.y = f.placement.location.y;
  r.top_z = f.placement.location.z;
  r.bottom_z = f.placement.location.z - f.depth;
  const Frame frame = frame_of(f);
  auto& p = r.profile;
  switch (f.kind) {
    case pr::FeatureKind::RoundHole:
      r.diameter = f.diameter;
      p.shape = fr::ProfileShape::Circular;
      p.diameter = f.diameter;
      r.bottom = f.bottom == pr::HoleBottom::Through ? fr::BottomCondition::Through
                 : f.bottom == pr::HoleBottom::Conical ? fr::BottomCondition::Conical
                                                        : fr::BottomCondition::Planar;
      if (f.bottom == pr::HoleBottom::Conical) r.bottom_angle_deg = f.tip_angle;
      return r;
    case pr::FeatureKind::Slot: {
      r.slot_width = f.width;
      r.slot_course = {frame.world(-f.length / 2, 0), frame.world(f.length / 2, 0)};
      for (std::size_t i = 0; i < 2; ++i) {
        r.slot_ends[i] = f.slot_ends[i] == pr::SlotEnd::Radiused ? fr::SlotEnd::Radiused
                         : f.slot_ends[i] == pr::SlotEnd::Flat   ? fr::SlotEnd::Flat
                                                                 : fr::SlotEnd::Open;
      }
      p.angle_deg = angle_of(frame.cx, frame.sx);
      r.bottom = f.through ? fr::BottomCondition::Through : fr::BottomCondition::Planar;
      return r;
    }
    default: break;
  }
  if (f.kind == pr::FeatureKind::ClosedPocket || f.kind == pr::FeatureKind::OpenPocket) {
    r.bottom = f.through ? fr::BottomCondition::Through : fr::BottomCondition::Planar;
  }
  if (f.outline == pr::Outline::Circle) {
    p.shape = fr::ProfileShape::Circular;
    p.diameter = f.diameter;
  } else if (f.outline == pr::Outline::Rectangle) {
    p.shape = fr::ProfileShape::Rectangular;
    p.length = f.length;
    p.width = f.width;
    p.corner_radius = f.corner_radius;
    double cx = frame.cx, sx = frame.sx;
    if (f.width > f.length) {  // `length` is the longer side
      std::swap(p.length, p.width);
      cx = -frame.sx, sx = frame.cx;
    }
    p.angle_deg = angle_of(cx, sx);
  } else {
    p.shape = fr::ProfileShape::GeneralClosed;
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const auto& [x, y] : outline_points(f.boundary)) {
      const fr::Point2 w = frame.world(x, y);
      p.outline.push_back(w);
      xmin = std::min(xmin, w.x), xmax = std::max(xmax, w.x), ymin = std::min(ymin, w.y), ymax = std::max(ymax, w.y);
    }
    p.length = std::max(xmax - xmin, ymax - ymin);
    p.width = std::min(xmax - xmin, ymax - ymin);
    p.angle_deg = xmax - xmin >= ymax - ymin ? 0 : 90;
  }
  // The sides of the part the feature opens to.
  if (f.kind == pr::FeatureKind::Step) {
    const fr::Point2 o = frame.world(0, 0), out = frame.world(0, -1);  // local -y points out of the part
    r.open_sides.push_back(side_of(out.x - o.x, out.y - o.y));
  } else if (f.kind == pr::FeatureKind::OpenPocket) {
    const std::size_t n = f.boundary.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (!f.boundary[i].open) continue;
      const fr::Point2 a = frame.world(f.boundary[i].x, f.boundary[i].y), b = frame.world(f.boundary[(i + 1) % n].x, f.boundary[(i + 1) % n].y);
      const fr::OpenSide s = side_of(b.y - a.y, -(b.x - a.x));  // right of a counter-clockwise edge: outside
      if (std::find(r.open_sides.begin(), r.open_sides.end(), s) == r.open_sides.end()) r.open_sides.push_back(s);
    }
  }
  return r;
}

fr::RecognizedOperation as_recognized(const sn::Project& project, const sn::Operation& op, double feature_depth) {
  fr::RecognizedOperation r;
  const auto& mop = sn::machining_operation(op);
  r.tool_number = project.tool(mop.its_tool).number;
  const auto& tech = project.technology(mop.its_technology);
  if (tech.feedrate) r.feed = tidy(*tech.feedrate * 60000);
  if (tech.spindle) r.spindle_rpm = tidy(std::abs(*tech.spindle) * 60);
  r.layers = 1;
  std::visit(
      [&](const auto& o) {
        using T = std::decay_t<decltype(o)>;
        if constexpr (std::is_base_of_v<sn::Two5DMillingOperation, T>) {
          if constexpr (std::is_same_v<T, sn::PlaneRoughMilling>) r.type = fr::OperationType::PlaneRoughMilling;
          else if constexpr (std::is_same_v<T, sn::PlaneFinishMilling>) r.type = fr::OperationType::PlaneFinishMilling;
          else if constexpr (std::is_same_v<T, sn::SideRoughMilling>) r.type = fr::OperationType::SideRoughMilling;
          else if constexpr (std::is_same_v<T, sn::SideFinishMilling>) r.type = fr::OperationType::SideFinishMilling;
          else if constexpr (std::is_same_v<T, sn::BottomAndSideRoughMilling>) r.type = fr::OperationType::BottomAndSideRoughMilling;
          else r.type = fr::OperationType::BottomAndSideFinishMilling;
          if (o.its_machining_strategy) {
            r.strategy = std::visit(
                [](const auto& s) {
                  using S = std::decay_t<decltype(s)>;
                  if constexpr (std::is_same_v<S, sn::Unidirectional>) return fr::Strategy::Unidirectional;
                  else if constexpr (std::is_same_v<S, sn::Bidirectional>) return fr::Strategy::Bidirectional;
                  else if constexpr (std::is_same_v<S, sn::ContourParallel>) return fr::Strategy::ContourParallel;
                  else if constexpr (std::is_same_v<S, sn::ContourSpiral>) return fr::Strategy::ContourSpiral;
                  else return fr::Strategy::CenterMilling;
                },
                *o.its_machining_strategy);
          }
          if (o.axial_cutting_depth) {
            r.axial_depth = *o.axial_cutting_depth;
            const double removed = feature_depth - o.allowance_bottom.value_or(0);
            r.layers = std::max(1, static_cast<int>(std::ceil(removed / *o.axial_cutting_depth - 1e-9)));
            if (std::is_same_v<T, sn::PlaneFinishMilling> && o.axial_cutting_depth) r.layers = 1;
          }
          if (o.radial_cutting_depth) r.radial_depth = *o.radial_cutting_depth;
          if (o.allowance_side) r.side_allowance = *o.allowance_side;
          if (o.allowance_bottom) r.bottom_allowance = *o.allowance_bottom;
        } else if constexpr (std::is_same_v<T, sn::MultistepDrilling>) {
          r.type = fr::OperationType::MultistepDrilling;
          r.strategy = fr::Strategy::Plunge;
          if (o.depth_of_step > 0 && o.cutting_depth) r.layers = static_cast<int>(std::ceil(*o.cutting_depth / o.depth_of_step - 1e-9));
          r.axial_depth = o.depth_of_step;
        } else if constexpr (std::is_same_v<T, sn::Drilling>) {
          r.type = fr::OperationType::Drilling;
          r.strategy = fr::Strategy::Plunge;
        } else if constexpr (std::is_same_v<T, sn::CenterDrilling>) {
          r.type = fr::OperationType::CenterDrilling;
          r.strategy = fr::Strategy::Plunge;
        } else if constexpr (std::is_same_v<T, sn::Reaming>) {
          r.type = fr::OperationType::Reaming;
          r.strategy = fr::Strategy::Plunge;
        } else if constexpr (std::is_same_v<T, sn::Tapping>) {
          r.type = fr::OperationType::Tapping;
          r.strategy = fr::Strategy::Plunge;
        } else if constexpr (std::is_same_v<T, sn::Boring> || std::is_same_v<T, sn::BackBoring>) {
          r.type = fr::OperationType::BoringOperation;
          r.strategy = fr::Strategy::Plunge;
        } else {
          r.type = fr::OperationType::FreeformOperation;
        }
      },
      op);
  return r;
}

}  // namespace

Cc2Output plan_as_cc2(const pr::Part& part, const process_planner::Plan& plan, const setup::Stock& stock) {
  Cc2Output out;
  out.stock = stock;
  out.project = plan.project;
  for (const auto& w : plan.warnings) out.warnings.push_back((w.where.empty() ? "" : w.where + ": ") + w.message);
  for (const auto& planned : plan.features) {
    const pr::Feature& f = part.features.at(planned.part_feature);
    fr::RecognizedFeature r = as_recognized(f);
    std::vector<std::string> workingsteps;
    for (std::size_t e : planned.workingsteps) {
      const auto& ws = std::get<sn::MachiningWorkingstep>(plan.project.main_workplan.its_elements.at(e));
      r.operations.push_back(as_recognized(plan.project, plan.project.operation(ws.its_operation), f.depth));
      r.operations.back().workingsteps.push_back(e);
      workingsteps.push_back(ws.its_id);
    }
    out.feature_ids.push_back(sn::feature_id(plan.project.feature({static_cast<std::uint32_t>(planned.project_feature)})));
    out.features.push_back(std::move(r));
    out.workingstep_ids.push_back(std::move(workingsteps));
  }
  return out;
}

nlohmann::ordered_json part_sections(const pr::Part& part, const process_planner::Plan& plan) {
  using json = nlohmann::ordered_json;
  json sections;
  json not_planned = json::array();
  for (const auto& f : part.features) {
    if (f.accessible) continue;
    json j;
    j["source"] = f.source;
    j["type"] = std::string(pr::to_string(f.kind));
    j["location"] = {tidy(f.placement.location.x), tidy(f.placement.location.y), tidy(f.placement.location.z)};
    j["axis"] = {tidy(f.placement.axis.x), tidy(f.placement.axis.y), tidy(f.placement.axis.z)};
    if (f.kind == pr::FeatureKind::RoundHole) {
      j["diameter"] = tidy(f.diameter);
      j["depth"] = tidy(f.depth);
      j["bottom_condition"] = std::string(pr::to_string(f.bottom));
    }
    for (const auto& w : part.warnings) {
      if (w.where == f.source && w.message.find("needs") != std::string::npos) j["reason"] = w.message;
    }
    not_planned.push_back(std::move(j));
  }
  sections["not_planned"] = not_planned;
  json compounds = json::array();
  for (const auto& c : part.compounds) {
    json j;
    j["kind"] = std::string(pr::to_string(c.kind));
    j["source"] = c.source;
    json elements = json::array();
    for (std::size_t e : c.elements) {
      std::string id;
      for (const auto& planned : plan.features) {
        if (planned.part_feature == e) id = sn::feature_id(plan.project.feature({static_cast<std::uint32_t>(planned.project_feature)}));
      }
      const auto& f = part.features.at(e);
      elements.push_back({{"id", id}, {"source", f.source}, {"diameter", tidy(f.diameter)}, {"depth", tidy(f.depth)},
                          {"bottom_condition", std::string(pr::to_string(f.bottom))}});
    }
    j["holes"] = elements;
    compounds.push_back(std::move(j));
  }
  sections["compounds"] = compounds;
  json listed = json::array();
  for (const auto& l : part.listed) {
    json parameters = json::object();
    for (const auto& p : l.parameters) parameters[p.name] = p.value;
    listed.push_back({{"entity", l.entity}, {"name", l.name}, {"source", l.source}, {"reason", l.reason}, {"parameters", parameters}});
  }
  sections["listed"] = listed;
  return sections;
}

}  // namespace ncbridge::cli
