#include "ncbridge/material_check/material_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <type_traits>

#include "ncbridge/material_check/polygon_set.hpp"

namespace ncbridge::material_check {

namespace {

namespace sn = stepnc;
constexpr double kPi = std::numbers::pi;
constexpr double kOutlineChord = 1e-4;  // mm: feature outlines as polygons for sampling
constexpr double kRapidClear = 1e-3;    // mm: a rapid grazing less than this is clear
constexpr std::size_t kMaxFindings = 50;

using Ring = std::vector<Point2>;

const sn::Two5DMillingOperation* as_milling(const sn::Operation& op) {
  return std::visit(
      [](const auto& o) -> const sn::Two5DMillingOperation* {
        if constexpr (std::is_base_of_v<sn::Two5DMillingOperation, std::decay_t<decltype(o)>>) return &o;
        else return nullptr;
      },
      op);
}

bool is_roughing(const sn::Operation& op) {
  return std::holds_alternative<sn::PlaneRoughMilling>(op) || std::holds_alternative<sn::SideRoughMilling>(op) ||
         std::holds_alternative<sn::BottomAndSideRoughMilling>(op);
}

// The height a scallop between passes `stepover` apart leaves under a ball or bull-nose cutter.
double scallop(const CutterShape& c, double stepover) {
  if (c.kind != CutterShape::Kind::Ball && c.kind != CutterShape::Kind::BullNose) return 0;
  const double flat = c.radius - c.corner_radius;
  const double gap = stepover - 2 * flat;
  if (gap <= 0) return 0;
  const double half = std::min(gap / 2, c.corner_radius);
  return c.corner_radius - std::sqrt(c.corner_radius * c.corner_radius - half * half);
}

std::vector<Ring> outline_rings(const FeatureRegion& r) {
  std::vector<Ring> rings;
  for (const auto& c : r.outline) rings.push_back(c.points(kOutlineChord));
  return rings;
}

struct RingBox {
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
  void add(Point2 p) {
    xmin = std::min(xmin, p.x), ymin = std::min(ymin, p.y), xmax = std::max(xmax, p.x), ymax = std::max(ymax, p.y);
  }
  bool holds(Point2 p, double margin) const {
    return p.x >= xmin - margin && p.x <= xmax + margin && p.y >= ymin - margin && p.y <= ymax + margin;
  }
};

RingBox box_of(const std::vector<Ring>& rings) {
  RingBox b;
  for (const auto& r : rings) {
    for (const auto& p : r) b.add(p);
  }
  return b;
}

// Calls f(i, j) for every grid sample inside the rings (even-odd), by scanlines.
template <class F>
void fill_rows(const std::vector<Ring>& rings, const HeightGrid& g, F&& f) {
  struct Edge {
    double ylo, yhi, x0, y0, slope;
  };
  std::vector<Edge> edges;
  for (const auto& r : rings) {
    for (std::size_t k = 0; k < r.size(); ++k) {
      const Point2 a = r[k], b = r[(k + 1) % r.size()];
      if (a.y == b.y) continue;
      edges.push_back({std::min(a.y, b.y), std::max(a.y, b.y), a.x, a.y, (b.x - a.x) / (b.y - a.y)});
    }
  }
  if (edges.empty()) return;
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) { return x.ylo < y.ylo; });
  double ymin = edges.front().ylo, ymax = -1e300;
  for (const auto& e : edges) ymax = std::max(ymax, e.yhi);
  std::vector<const Edge*> active;
  std::vector<double> xs;
  std::size_t next = 0;
  for (int j = g.first_row(ymin), j1 = g.last_row(ymax); j <= j1; ++j) {
    const double y = g.y(j);
    while (next < edges.size() && edges[next].ylo <= y) active.push_back(&edges[next++]);
    active.erase(std::remove_if(active.begin(), active.end(), [&](const Edge* e) { return e->yhi <= y; }), active.end());
    xs.clear();
    for (const auto* e : active) {
      if (e->ylo <= y && y < e->yhi) xs.push_back(e->x0 + (y - e->y0) * e->slope);
    }
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      for (int i = g.first_column(xs[k]), i1 = g.last_column(xs[k + 1]); i <= i1; ++i) f(i, j);
    }
  }
}

bool inside_rings(const std::vector<Ring>& rings, Point2 p) {
  bool in = false;
  for (const auto& r : rings) {
    for (std::size_t k = 0, n = r.size(); k < n; ++k) {
      const Point2 a = r[k], b = r[(k + 1) % n];
      if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
  }
  return in;
}

double segment_distance(Point2 p, Point2 a, Point2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, L2 = dx * dx + dy * dy;
  const double t = L2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / L2, 0.0, 1.0) : 0;
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

double boundary_distance(const std::vector<Ring>& rings, Point2 p) {
  double d = 1e300;
  for (const auto& r : rings) {
    for (std::size_t k = 0, n = r.size(); k < n; ++k) d = std::min(d, segment_distance(p, r[k], r[(k + 1) % n]));
  }
  return d;
}

double floor_at(const FeatureRegion& r, Point2 p) {
  if (!r.cone_tip_angle) return r.floor_z;
  const double d = std::hypot(p.x - r.frame.origin.x, p.y - r.frame.origin.y);
  return std::min(r.top_z, r.floor_z + d / std::tan(*r.cone_tip_angle / 2 * kPi / 180));
}

// How deep a cut may go without gouging: a through feature may break out below the part's bottom.
double deepest_at(const FeatureRegion& r, Point2 p) { return r.through ? -1e30 : floor_at(r, p); }

double motion_length(const Point3& from, const Motion& m) {
  const double dz = m.end.z - from.z;
  if (m.arc_centre) {
    const double r = std::hypot(from.x - m.arc_centre->x, from.y - m.arc_centre->y);
    return std::hypot(r * std::abs(m.arc_sweep), dz);
  }
  return std::sqrt((m.end.x - from.x) * (m.end.x - from.x) + (m.end.y - from.y) * (m.end.y - from.y) + dz * dz);
}

struct RunFigures {
  std::size_t rapid_collisions = 0, plunges = 0;
  double max_rapid = 0, max_plunge = 0, removed = 0, feed = 0, air = 0;
  std::vector<Finding> findings;
};

RunFigures run_program(const ToolpathProgram& program, MaterialSimulation& sim, double tolerance, double steep_deg) {
  RunFigures out;
  const double steep = std::tan(steep_deg * kPi / 180);
  for (const auto& run : program.runs) {
    Point3 at = run.start;
    for (const auto& m : run.motions) {
      // Straight up is always clear in 2.5D: the cutter leaves the way it came.
      const bool retract = !m.arc_centre && m.end.z > at.z && std::abs(m.end.x - at.x) < 1e-9 && std::abs(m.end.y - at.y) < 1e-9;
      if (m.rapid && !retract) {
        const double d = sim.penetration(at, m, run.cutter);
        if (d > kRapidClear) {
          ++out.rapid_collisions;
          out.max_rapid = std::max(out.max_rapid, d);
          if (out.findings.size() < kMaxFindings) out.findings.push_back({Finding::Kind::RapidThroughMaterial, run.workingstep, at, m.end, d});
        }
      } else if (!m.rapid) {
        const CutResult cut = sim.feed(at, m, run.cutter);
        const double length = motion_length(at, m);
        out.feed += length;
        if (!cut.removed) out.air += length;
        out.removed += cut.removed_volume;
        const double horizontal = std::hypot(m.end.x - at.x, m.end.y - at.y);
        const bool steep_descent = !m.arc_centre && at.z - m.end.z > steep * horizontal;
        if (!run.drilling && run.cutter.kind != CutterShape::Kind::Cone && steep_descent && cut.centre_depth > tolerance) {
          ++out.plunges;
          out.max_plunge = std::max(out.max_plunge, cut.centre_depth);
          if (out.findings.size() < kMaxFindings) out.findings.push_back({Finding::Kind::Plunge, run.workingstep, at, m.end, cut.centre_depth});
        }
      }
      at = m.end;
    }
  }
  return out;
}

std::vector<Point2> wall_probes(const DesignedPart& part, double spacing, double offset) {
  std::vector<Point2> probes;
  const auto& s = part.stock;
  auto in_stock = [&](Point2 p) { return p.x > s.min[0] && p.x < s.max[0] && p.y > s.min[1] && p.y < s.max[1]; };
  for (const auto& f : part.features) {
    for (const auto& curve : f.region.outline) {
      for (const auto& seg : curve.segments) {
        const double length = length_of(seg);
        const int n = std::max(1, static_cast<int>(std::ceil(length / spacing)));
        for (int k = 0; k < n; ++k) {
          const double t = (k + 0.5) / n;
          Point2 p, tangent;
          if (const auto* l = std::get_if<LineSegment>(&seg)) {
            p = {l->a.x + t * (l->b.x - l->a.x), l->a.y + t * (l->b.y - l->a.y)};
            tangent = {(l->b.x - l->a.x) / length, (l->b.y - l->a.y) / length};
          } else {
            const auto& a = std::get<ArcSegment>(seg);
            const double ang = a.start_angle + a.sweep * t;
            p = a.at(t);
            const double sign = a.sweep > 0 ? 1 : -1;
            tangent = {-std::sin(ang) * sign, std::cos(ang) * sign};
          }
          const Point2 left{-tangent.y, tangent.x};
          for (double side : {offset, -offset}) {
            const Point2 q{p.x + left.x * side, p.y + left.y * side};
            if (in_stock(q)) probes.push_back(q);
          }
        }
      }
    }
  }
  return probes;
}

}  // namespace

DesignedPart designed_part(const sn::Project& cc2, const setup::Stock& stock, const std::string& source) {
  DesignedPart part;
  part.stock = stock;
  std::map<std::uint32_t, std::size_t> index_of;  // project feature -> designed feature
  for (const auto& e : cc2.main_workplan.its_elements) {
    const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e);
    if (!ws) continue;
    const auto& feature = cc2.feature(ws->its_feature);
    if (std::holds_alternative<sn::ToolpathFeature>(feature)) continue;
    auto it = index_of.find(ws->its_feature.index);
    if (it == index_of.end()) {
      DesignedFeature d;
      d.region = feature_region(feature, ws->its_feature.index, stock, source);
      part.features.push_back(std::move(d));
      it = index_of.emplace(ws->its_feature.index, part.features.size() - 1).first;
    }
    auto& d = part.features[it->second];
    const auto& op = cc2.operation(ws->its_operation);
    const auto& tool = cc2.tool(sn::machining_operation(op).its_tool);
    const CutterShape cutter = cutter_of(tool);
    if (const auto* m = as_milling(op)) {
      if (d.reach_radius == 0 || cutter.radius < d.reach_radius) {
        d.reach_radius = cutter.radius;
        d.reach_corner_radius = cutter.kind == CutterShape::Kind::Flat ? 0 : cutter.corner_radius;
      }
      // What the latest operation leaves: its allowances when it roughs, its scallop.
      d.allowed_leftover = 0;
      d.allowance_side = 0;
      if (is_roughing(op)) {
        d.allowance_side = std::max(0.0, m->allowance_side.value_or(0));
        d.allowed_leftover = std::max(0.0, m->allowance_bottom.value_or(0));
      }
      if (m->radial_cutting_depth) d.allowed_leftover += scallop(cutter, *m->radial_cutting_depth);
    } else {
      d.allowed_leftover = 0;
      d.allowance_side = 0;
    }
  }
  return part;
}

double MaterialReport::max_leftover() const {
  double m = 0;
  for (const auto& f : features) m = std::max(m, f.max_leftover);
  return m;
}

double MaterialReport::least_reached() const {
  double m = 1;
  for (const auto& f : features) m = std::min(m, f.reached_fraction);
  return m;
}

bool MaterialReport::clean(double tolerance) const {
  if (max_gouge > tolerance || rapid_collisions > 0 || plunges > 0) return false;
  return std::all_of(features.begin(), features.end(), [](const FeatureFigures& f) { return f.reached_fraction >= 1.0; });
}

MaterialReport check_material(const ToolpathProgram& program, const DesignedPart& part, const CheckOptions& options) {
  MaterialReport report;
  const auto& stock = part.stock;
  const double cell = options.cell > 0 ? options.cell : automatic_cell(stock);
  report.cell = cell;
  MaterialSimulation sim(stock, cell, wall_probes(part, std::max(cell, 0.05), options.probe_offset));
  const RunFigures run = run_program(program, sim, options.tolerance, options.steep_descent_deg);
  report.rapid_collisions = run.rapid_collisions;
  report.max_rapid_depth = run.max_rapid;
  report.plunges = run.plunges;
  report.max_plunge_depth = run.max_plunge;
  report.findings = run.findings;
  report.removed_volume = run.removed;
  report.feed_length = run.feed;
  report.air_feed_length = run.air;

  const HeightGrid& g = sim.grid();
  const std::size_t n = g.size();
  report.samples = n;
  report.probes = sim.probes().size();
  const float top = static_cast<float>(stock.max[2]);
  std::vector<float> high(n, top), low(n, top);
  std::vector<std::int32_t> owner(n, -1), band(n, -1);
  const auto& probes = sim.probes();
  std::vector<float> probe_high(probes.size(), top), probe_low(probes.size(), top);
  std::vector<std::int32_t> probe_owner(probes.size(), -1);

  std::vector<std::vector<Ring>> rings(part.features.size());
  std::vector<RingBox> boxes(part.features.size());
  for (std::size_t f = 0; f < part.features.size(); ++f) {
    const auto& region = part.features[f].region;
    rings[f] = outline_rings(region);
    boxes[f] = box_of(rings[f]);
    const auto id = static_cast<std::int32_t>(f);
    // Samples within the band of a wall: as deep as the feature goes (for gouges), not as
    // its inside (for leftovers).
    const double eps = options.wall_band;
    for (const auto& r : rings[f]) {
      for (std::size_t k = 0; k < r.size(); ++k) {
        const Point2 a = r[k], b = r[(k + 1) % r.size()];
        for (int j = g.first_row(std::min(a.y, b.y) - eps), j1 = g.last_row(std::max(a.y, b.y) + eps); j <= j1; ++j) {
          for (int i = g.first_column(std::min(a.x, b.x) - eps), i1 = g.last_column(std::max(a.x, b.x) + eps); i <= i1; ++i) {
            const Point2 p{g.x(i), g.y(j)};
            if (segment_distance(p, a, b) > eps) continue;
            const std::size_t s = static_cast<std::size_t>(j) * g.nx() + i;
            band[s] = id;
            low[s] = std::min(low[s], static_cast<float>(deepest_at(region, p)));
          }
        }
      }
    }
    fill_rows(rings[f], g, [&](int i, int j) {
      const std::size_t s = static_cast<std::size_t>(j) * g.nx() + i;
      const float z = static_cast<float>(floor_at(region, {g.x(i), g.y(j)}));
      low[s] = std::min(low[s], static_cast<float>(deepest_at(region, {g.x(i), g.y(j)})));
      if (band[s] != id && z < high[s]) high[s] = z, owner[s] = id;
    });
  }
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const Point2 p = probes[k];
    for (std::size_t f = 0; f < part.features.size(); ++f) {
      if (!boxes[f].holds(p, options.wall_band)) continue;
      const bool in = inside_rings(rings[f], p);
      const bool near = boundary_distance(rings[f], p) <= options.wall_band;
      if (!in && !near) continue;
      const float z = static_cast<float>(floor_at(part.features[f].region, p));
      probe_low[k] = std::min(probe_low[k], static_cast<float>(deepest_at(part.features[f].region, p)));
      if (in && !near && z < probe_high[k]) probe_high[k] = z, probe_owner[k] = static_cast<std::int32_t>(f);
    }
  }

  // Gouges.
  const auto& heights = g.heights();
  const double cell_area = cell * cell;
  auto note_gouge = [&](double depth, Point2 p, double z) {
    if (depth > report.max_gouge) report.max_gouge = depth, report.max_gouge_at = {p.x, p.y, z};
  };
  for (std::size_t s = 0; s < n; ++s) {
    const double depth = static_cast<double>(low[s]) - heights[s];
    if (depth > options.tolerance) report.gouge_area += cell_area;
    if (depth > 0) note_gouge(depth, {g.x(static_cast<int>(s % g.nx())), g.y(static_cast<int>(s / g.nx()))}, heights[s]);
  }
  const auto& probe_heights = sim.probe_heights();
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const double depth = static_cast<double>(probe_low[k]) - probe_heights[k];
    if (depth > 0) note_gouge(depth, probes[k], probe_heights[k]);
  }

  // Per feature: what is left on its floor and walls, where its tools reach.
  const double outside = 1e4;
  const PolygonSet outside_stock = PolygonSet::rectangle({stock.min[0] - outside, stock.min[1] - outside, stock.max[0] + outside,
                                                          stock.max[1] + outside})
                                       .minus(PolygonSet::rectangle({stock.min[0], stock.min[1], stock.max[0], stock.max[1]}));
  std::vector<PolygonSet> polygons(part.features.size());
  for (std::size_t f = 0; f < part.features.size(); ++f) polygons[f] = PolygonSet::from_rings(rings[f]);
  for (std::size_t f = 0; f < part.features.size(); ++f) {
    const auto& d = part.features[f];
    const auto id = static_cast<std::int32_t>(f);
    FeatureFigures fig;
    fig.id = d.region.id;
    fig.floor_z = d.region.floor_z;
    fig.through = d.region.through;
    fig.allowed_leftover = options.tolerance + d.allowed_leftover;
    std::size_t owned = 0, reachable = 0, reached = 0;
    auto look = [&](float sim_z, float design_z, Point2 p) {
      ++fig.samples;
      const double left = static_cast<double>(sim_z) - design_z;
      if (left <= fig.allowed_leftover) ++reached;
      if (left > fig.max_leftover) fig.max_leftover = left, fig.max_leftover_at = {p.x, p.y, sim_z};
    };
    for (std::size_t s = 0; s < n; ++s) owned += owner[s] == id;
    std::optional<PolygonSet> reach;
    if (d.reach_radius > 0) {
      const double R = d.reach_radius, margin = 2 * (R + d.allowance_side) + 1;
      const RingBox& b = boxes[f];
      PolygonSet free = polygons[f].united(outside_stock);
      for (std::size_t h = 0; h < part.features.size(); ++h) {
        if (h == f || part.features[h].region.floor_z > d.region.floor_z + 1e-6) continue;
        const RingBox& o = boxes[h];
        if (o.xmin > b.xmax + margin || o.xmax < b.xmin - margin || o.ymin > b.ymax + margin || o.ymax < b.ymin - margin) continue;
        free = free.united(polygons[h]);
      }
      // Eroded a hair less than the radius (a slot exactly as wide as the cutter stays
      // reachable), grown back less the tolerance (no sliver of a corner counts as reached).
      const double slack = 0.002;
      reach = free.offset(-(R + d.allowance_side - slack), 0.001)
                  .offset(R - d.reach_corner_radius - options.tolerance + slack, 0.001);
      std::vector<Ring> reach_rings = reach->rings();
      fill_rows(reach_rings, g, [&](int i, int j) {
        const std::size_t s = static_cast<std::size_t>(j) * g.nx() + i;
        if (owner[s] != id) return;
        ++reachable;
        look(heights[s], high[s], {g.x(i), g.y(j)});
      });
    } else {
      for (std::size_t s = 0; s < n; ++s) {
        if (owner[s] != id) continue;
        ++reachable;
        look(heights[s], high[s], {g.x(static_cast<int>(s % g.nx())), g.y(static_cast<int>(s / g.nx()))});
      }
    }
    for (std::size_t k = 0; k < probes.size(); ++k) {
      if (probe_owner[k] != id) continue;
      if (reach && !reach->contains(probes[k])) continue;
      look(probe_heights[k], probe_high[k], probes[k]);
    }
    fig.area = static_cast<double>(owned) * cell_area;
    fig.unreachable_area = static_cast<double>(owned - std::min(owned, reachable)) * cell_area;
    fig.reached_fraction = fig.samples > 0 ? static_cast<double>(reached) / static_cast<double>(fig.samples) : 1.0;
    report.features.push_back(std::move(fig));
  }
  return report;
}

Simulated simulate(const ToolpathProgram& program, const setup::Stock& stock, double cell) {
  MaterialSimulation sim(stock, cell);
  const RunFigures run = run_program(program, sim, 0.01, 30);
  Simulated out;
  out.grid = sim.grid();
  out.rapid_collisions = run.rapid_collisions;
  out.plunges = run.plunges;
  out.removed_volume = run.removed;
  return out;
}

MaterialDifference compare_material(const HeightGrid& a, const HeightGrid& b, double tolerance) {
  MaterialDifference out;
  if (a.nx() != b.nx() || a.ny() != b.ny()) throw std::invalid_argument("material check: the grids differ in size");
  const double cell_area = a.cell() * a.cell();
  float top = -std::numeric_limits<float>::infinity();
  for (float h : a.heights()) top = std::max(top, h);
  for (float h : b.heights()) top = std::max(top, h);
  for (int j = 0; j < a.ny(); ++j) {
    for (int i = 0; i < a.nx(); ++i) {
      const double ha = a.height(i, j), hb = b.height(i, j);
      out.volume_a += (top - ha) * cell_area;
      out.volume_b += (top - hb) * cell_area;
      const double diff = ha - hb;
      if (std::abs(diff) > tolerance) out.differing_area += cell_area;
      if (diff > out.max_deeper) out.max_deeper = diff, out.max_deeper_at = {a.x(i), a.y(j), hb};
      if (-diff > out.max_shallower) out.max_shallower = -diff, out.max_shallower_at = {a.x(i), a.y(j), hb};
    }
  }
  return out;
}

}  // namespace ncbridge::material_check
