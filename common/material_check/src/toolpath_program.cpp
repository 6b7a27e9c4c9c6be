#include "ncbridge/material_check/toolpath_program.hpp"

#include <cmath>
#include <numbers>
#include <type_traits>

namespace ncbridge::material_check {

namespace {

namespace sn = stepnc;
constexpr double kPi = std::numbers::pi;
constexpr double kChord = 0.001;  // mm: arcs out of the XY plane as chords

Point3 point(const sn::CartesianPoint& p) { return {p.x, p.y, p.z}; }

bool same(const Point3& a, const Point3& b) {
  return std::abs(a.x - b.x) < 1e-9 && std::abs(a.y - b.y) < 1e-9 && std::abs(a.z - b.z) < 1e-9;
}

void append_curve(const sn::CompositeCurve& curve, bool rapid, Point3& at, std::vector<Motion>& out) {
  auto line_to = [&](const Point3& q) {
    if (same(q, at)) return;
    Motion m;
    m.rapid = rapid;
    m.end = q;
    out.push_back(m);
    at = q;
  };
  for (const auto& segment : curve.segments) {
    if (const auto* line = std::get_if<sn::Polyline>(&segment)) {
      for (const auto& p : line->points) line_to(point(p));
      continue;
    }
    const auto& arc = std::get<sn::TrimmedCircle>(segment);
    line_to(point(arc.trim_1_point));
    const auto& ax = arc.position.axis;
    const double sweep = sn::sweep_degrees(arc) * kPi / 180;
    if (std::abs(ax.x) < 1e-9 && std::abs(ax.y) < 1e-9) {
      const bool ccw = arc.sense_agreement == (ax.z > 0);
      Motion m;
      m.rapid = rapid;
      m.end = point(arc.trim_2_point);
      m.arc_centre = Point2{arc.position.location.x, arc.position.location.y};
      m.arc_sweep = ccw ? sweep : -sweep;
      out.push_back(m);
      at = m.end;
      continue;
    }
    // An arc in another plane: chords of the circle (the trims' z along its own axis).
    const auto& c = arc.position.location;
    const auto& u = arc.position.ref_direction;
    const sn::Direction v{ax.y * u.z - ax.z * u.y, ax.z * u.x - ax.x * u.z, ax.x * u.y - ax.y * u.x};
    const double step = kChord < arc.radius ? 2 * std::acos(1 - kChord / arc.radius) : kPi / 2;
    const int n = std::max(1, static_cast<int>(std::ceil(sweep / step)));
    const double t0 = arc.trim_1_parameter * kPi / 180, sign = arc.sense_agreement ? 1 : -1;
    for (int k = 1; k <= n; ++k) {
      const double t = t0 + sign * sweep * k / n;
      const Point3 q = k == n ? point(arc.trim_2_point)
                              : Point3{c.x + arc.radius * (std::cos(t) * u.x + std::sin(t) * v.x),
                                       c.y + arc.radius * (std::cos(t) * u.y + std::sin(t) * v.y),
                                       c.z + arc.radius * (std::cos(t) * u.z + std::sin(t) * v.z)};
      line_to(q);
    }
  }
}

const sn::DrillingTypeOperation* as_drilling(const sn::Operation& op) {
  return std::visit(
      [](const auto& o) -> const sn::DrillingTypeOperation* {
        if constexpr (std::is_base_of_v<sn::DrillingTypeOperation, std::decay_t<decltype(o)>>) return &o;
        else return nullptr;
      },
      op);
}

}  // namespace

ToolpathProgram program_from_stepnc(const sn::Project& project, std::optional<Point3> start) {
  ToolpathProgram program;
  std::vector<Motion> pending;  // rapid movements waiting for the next workingstep's tool
  std::string pending_id;
  bool started = start.has_value();
  Point3 at = start.value_or(Point3{});
  const double security = project.setup.its_secplane.position.location.z;
  auto begin_at = [&](const Point3& first) {
    if (started) return;
    at = {first.x, first.y, std::max(first.z, security)};
    started = true;
  };
  auto first_point = [](const sn::CompositeCurve& c) -> std::optional<Point3> {
    for (const auto& s : c.segments) {
      if (const auto* l = std::get_if<sn::Polyline>(&s)) {
        if (!l->points.empty()) return point(l->points.front());
      } else {
        return point(std::get<sn::TrimmedCircle>(s).trim_1_point);
      }
    }
    return std::nullopt;
  };
  Point3 pending_start;
  for (const auto& element : project.main_workplan.its_elements) {
    if (const auto* rapid = std::get_if<sn::RapidMovement>(&element)) {
      if (!rapid->its_toolpath) continue;
      for (const auto& t : rapid->its_toolpath->its_list) {
        if (auto p = first_point(t.basiccurve)) begin_at(*p);
        if (pending.empty()) pending_start = at;
        append_curve(t.basiccurve, true, at, pending);
      }
      if (pending_id.empty()) pending_id = rapid->its_id;
      continue;
    }
    // A retract straight up that starts the rapids is still made by the previous tool.
    if (!program.runs.empty()) {
      std::size_t k = 0;
      Point3 p = pending_start;
      while (k < pending.size() && !pending[k].arc_centre && std::abs(pending[k].end.x - p.x) < 1e-9 &&
             std::abs(pending[k].end.y - p.y) < 1e-9 && pending[k].end.z >= p.z) {
        p = pending[k].end;
        ++k;
      }
      auto& previous = program.runs.back().motions;
      previous.insert(previous.end(), pending.begin(), pending.begin() + static_cast<std::ptrdiff_t>(k));
      pending.erase(pending.begin(), pending.begin() + static_cast<std::ptrdiff_t>(k));
      pending_start = p;
    }
    const auto& ws = std::get<sn::MachiningWorkingstep>(element);
    const auto& op = project.operation(ws.its_operation);
    const auto& mop = sn::machining_operation(op);
    ToolRun run;
    run.workingstep = ws.its_id;
    const auto& tool = project.tool(mop.its_tool);
    run.tool = tool.its_id;
    run.cutter = cutter_of(tool);
    const auto* drilling = as_drilling(op);
    run.drilling = drilling != nullptr;
    const auto& feature = project.feature(ws.its_feature);
    const auto* hole = std::get_if<sn::RoundHole>(&feature);
    if (hole && drilling && !mop.its_toolpath) {
      const auto& pl = hole->feature_placement;
      const double sign = pl.axis.z < 0 ? -1 : 1;
      const double top = pl.location.z;
      const double depth = drilling->cutting_depth.value_or(-hole->depth.position.location.z);
      const double bottom = top - sign * depth;
      const double clear = top + sign * mop.retract_plane.value_or(0);
      begin_at({pl.location.x, pl.location.y, clear});
      run.start = pending.empty() ? at : pending_start;
      run.motions = std::move(pending);
      auto add = [&](bool rapid, Point3 q) {
        if (same(q, at)) return;
        Motion m;
        m.rapid = rapid;
        m.end = q;
        run.motions.push_back(m);
        at = q;
      };
      if (at.z < clear) add(true, {at.x, at.y, clear});
      add(true, {pl.location.x, pl.location.y, at.z});
      add(true, {pl.location.x, pl.location.y, clear});
      add(false, {pl.location.x, pl.location.y, bottom});
      add(true, {pl.location.x, pl.location.y, clear});
    } else {
      if (mop.its_toolpath) {
        for (const auto& t : mop.its_toolpath->its_list) {
          if (auto p = first_point(t.basiccurve)) {
            begin_at(*p);
            break;
          }
        }
      }
      run.start = pending.empty() ? at : pending_start;
      run.motions = std::move(pending);
      if (mop.its_toolpath) {
        for (const auto& t : mop.its_toolpath->its_list) {
          const bool rapid = t.its_type == sn::ToolpathType::Connect || t.its_type == sn::ToolpathType::NonContact;
          append_curve(t.basiccurve, rapid, at, run.motions);
        }
      }
    }
    pending.clear();
    pending_id.clear();
    program.runs.push_back(std::move(run));
  }
  if (!pending.empty()) {
    ToolRun tail;
    tail.workingstep = pending_id;
    if (!program.runs.empty()) {
      tail.tool = program.runs.back().tool;
      tail.cutter = program.runs.back().cutter;
    }
    tail.start = pending_start;
    tail.motions = std::move(pending);
    if (tail.cutter.radius > 0) program.runs.push_back(std::move(tail));
  }
  return program;
}

}  // namespace ncbridge::material_check
