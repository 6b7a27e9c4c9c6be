// Pockets, slots, steps and open pockets from their floors: the faces facing up below the
// part's top that no hole took, joined where they meet at one height. Each edge of a floor's
// outer loop is a wall (a face rising from it, the edge concave) or open (the material drops
// away: the part's side, a deeper feature). All walls: a closed pocket (rectangular with corner
// radius, circular, or of any outline) or a closed slot with round ends; two straight parallel
// walls and open ends: a through slot; one straight wall: a step; otherwise an open pocket.
// The feature reaches from its floor up to the top of its walls.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include "brep_recognize.hpp"

namespace ncbridge::part_reader::brep {

namespace {

struct Labelled {
  const OrientedEdge* edge;
  int face, other;
  bool wall;
};

Vec3 normal_at(const Surface& s, Vec3 p) {
  switch (s.kind) {
    case SurfaceKind::Plane: return s.axis;
    case SurfaceKind::Cylinder:
    case SurfaceKind::Cone: {
      const Vec3 a = unit(s.axis);
      const Vec3 radial = unit(p - (s.origin + dot(p - s.origin, a) * a));
      return s.concave ? -1.0 * radial : radial;
    }
    case SurfaceKind::Sphere: {
      const Vec3 radial = unit(p - s.origin);
      return s.concave ? -1.0 * radial : radial;
    }
    default: return {0, 0, 0};
  }
}

bool rises_as_wall(const Model& m, const OrientedEdge& e, int other, double z) {
  if (other < 0) return false;
  const Face& o = m.faces[static_cast<std::size_t>(other)];
  const std::size_t mid = e.points.size() / 2;
  const Vec3 a = e.points[mid > 0 ? mid - 1 : 0], b = e.points[std::min(mid + 1, e.points.size() - 1)];
  const Vec3 tangent = unit(b - a);
  const Vec3 inward{-tangent.y, tangent.x, 0};  // left of a counter-clockwise loop: the floor
  const Vec3 n = normal_at(o.surface, e.points[mid]);
  if (norm(n) == 0) return o.box_max.z > z + kTol && o.box_min.z > z - kTol;
  return dot(n, inward) > 0.2 && o.box_max.z > z + kTol;
}

bool straight(const std::vector<Labelled>& run, Vec3& point, Vec3& direction) {
  for (const auto& l : run) {
    if (l.edge->kind != CurveKind::Line) return false;
  }
  point = run.front().edge->start;
  direction = unit(run.front().edge->end - run.front().edge->start);
  for (const auto& l : run) {
    for (const Vec3& p : {l.edge->start, l.edge->end}) {
      const Vec3 d = p - point;
      if (norm(d - dot(d, direction) * direction) > kTol) return false;
    }
  }
  return true;
}

// Cyclic runs of edges with the same label, starting at a change.
std::vector<std::vector<Labelled>> runs_of(const std::vector<Labelled>& edges) {
  std::vector<std::vector<Labelled>> runs;
  const std::size_t n = edges.size();
  std::size_t start = 0;
  while (start < n && edges[start].wall == edges[(start + n - 1) % n].wall) ++start;
  if (start == n) return {edges};
  for (std::size_t k = 0; k < n; ++k) {
    const auto& e = edges[(start + k) % n];
    if (runs.empty() || runs.back().front().wall != e.wall) runs.emplace_back();
    runs.back().push_back(e);
  }
  return runs;
}

// Consecutive arcs on one circle as one arc (exporters split them).
struct Piece {
  CurveKind kind;
  Vec3 start, end, centre;
  double radius = 0, sweep = 0;  // sweep signed about +z
};

std::vector<Piece> pieces_of(const std::vector<Labelled>& edges) {
  std::vector<Piece> out;
  for (const auto& l : edges) {
    const OrientedEdge& e = *l.edge;
    Piece p{e.kind, e.start, e.end, e.centre, e.radius, 0};
    if (e.kind == CurveKind::Circle) p.sweep = e.axis.z >= 0 ? e.sweep : -e.sweep;
    if (!out.empty() && p.kind == CurveKind::Circle && out.back().kind == CurveKind::Circle &&
        norm(out.back().centre - p.centre) < kTol && std::abs(out.back().radius - p.radius) < kTol && out.back().sweep * p.sweep > 0) {
      out.back().end = p.end;
      out.back().sweep += p.sweep;
      continue;
    }
    out.push_back(p);
  }
  if (out.size() > 1 && out.front().kind == CurveKind::Circle && out.back().kind == CurveKind::Circle &&
      norm(out.front().centre - out.back().centre) < kTol && std::abs(out.front().radius - out.back().radius) < kTol &&
      out.front().sweep * out.back().sweep > 0) {
    out.front().start = out.back().start;
    out.front().sweep += out.back().sweep;
    out.pop_back();
  }
  return out;
}

void set_ref(Feature& f, Vec3 u) {
  f.placement.axis = {0, 0, 1};
  f.placement.ref_direction = {u.x, u.y, 0};
}

// Extent of the points of `edges` along u and v = z x u.
void extent(const std::vector<Labelled>& edges, Vec3 u, double& u0, double& u1, double& v0, double& v1) {
  const Vec3 v{-u.y, u.x, 0};
  u0 = v0 = 1e300, u1 = v1 = -1e300;
  for (const auto& l : edges) {
    for (const auto& p : l.edge->points) {
      u0 = std::min(u0, dot(p, u)), u1 = std::max(u1, dot(p, u));
      v0 = std::min(v0, dot(p, v)), v1 = std::max(v1, dot(p, v));
    }
  }
}

// Where a line (point + t u) runs inside the footprint: the span around t = `near`.
std::optional<std::pair<double, double>> span_in(const std::vector<OutlineVertex>& footprint, Vec3 point, Vec3 u, double near) {
  if (footprint.size() < 3) return std::nullopt;
  // The footprint as chords (arcs finely).
  std::vector<std::pair<double, double>> pts;
  const std::size_t n = footprint.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = footprint[i];
    const auto& b = footprint[(i + 1) % n];
    pts.emplace_back(a.x, a.y);
    if (a.bulge == 0) continue;
    const double chord = std::hypot(b.x - a.x, b.y - a.y);
    const double d = chord * (1 - a.bulge * a.bulge) / (4 * a.bulge);
    const double cx = (a.x + b.x) / 2 - (b.y - a.y) / chord * d, cy = (a.y + b.y) / 2 + (b.x - a.x) / chord * d;
    const double r = std::hypot(a.x - cx, a.y - cy), t0 = std::atan2(a.y - cy, a.x - cx), sweep = 4 * std::atan(a.bulge);
    for (int k = 1; k < 32; ++k) pts.emplace_back(cx + r * std::cos(t0 + sweep * k / 32), cy + r * std::sin(t0 + sweep * k / 32));
  }
  const Vec3 v{-u.y, u.x, 0};
  const double c = dot(point, v);
  std::vector<double> crossings;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto [ax, ay] = pts[i];
    const auto [bx, by] = pts[(i + 1) % pts.size()];
    const double sa = ax * v.x + ay * v.y - c, sb = bx * v.x + by * v.y - c;
    if ((sa > 0) == (sb > 0)) continue;
    const double t = sa / (sa - sb);
    crossings.push_back((ax + t * (bx - ax)) * u.x + (ay + t * (by - ay)) * u.y);
  }
  std::sort(crossings.begin(), crossings.end());
  for (std::size_t i = 0; i + 1 < crossings.size(); i += 2) {
    if (crossings[i] <= near + kTol && near - kTol <= crossings[i + 1]) return std::make_pair(crossings[i], crossings[i + 1]);
  }
  return std::nullopt;
}

std::vector<OutlineVertex> local(const std::vector<OutlineVertex>& world, const Feature& f) {
  const double cx = f.placement.ref_direction.x, sx = f.placement.ref_direction.y;
  std::vector<OutlineVertex> out;
  for (auto v : world) {
    const double dx = v.x - f.placement.location.x, dy = v.y - f.placement.location.y;
    v.x = dx * cx + dy * sx;
    v.y = -dx * sx + dy * cx;
    out.push_back(v);
  }
  return out;
}

bool inside(const std::vector<Vec3>& polygon, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec3& a = polygon[i];
    const Vec3& b = polygon[j];
    if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

std::vector<Vec3> points_of(const Loop& loop) {
  std::vector<Vec3> p;
  for (const auto& e : loop.edges) p.insert(p.end(), e.points.begin(), e.points.end());
  return p;
}

// A face facing down above the floor, over it: the floor is not reached from above (it is the
// wall of a feature made from the side).
int ceiling_over(const Model& m, const Chain& outer, double z) {
  std::vector<std::pair<double, double>> samples;
  for (const auto& b : outer) {
    const auto& p = b.edge->points;
    const std::size_t mid = p.size() / 2;
    const Vec3 t = unit(p[std::min(mid + 1, p.size() - 1)] - p[mid > 0 ? mid - 1 : 0]);
    samples.emplace_back(p[mid].x - 0.1 * t.y, p[mid].y + 0.1 * t.x);
  }
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    const Face& c = m.faces[i];
    if (c.surface.kind != SurfaceKind::Plane || c.surface.axis.z > -1 + 1e-6 || c.box_min.z < z + kTol || c.loops.empty()) continue;
    const auto outline = points_of(c.loops.front());
    for (const auto& [x, y] : samples) {
      if (!inside(outline, x, y)) continue;
      bool in_hole = false;
      for (std::size_t k = 1; k < c.loops.size(); ++k) in_hole = in_hole || inside(points_of(c.loops[k]), x, y);
      if (!in_hole) return static_cast<int>(i);
    }
  }
  return -1;
}

}  // namespace

void recognize_floors(const Model& m, Recognized& out) {
  // Floors, joined where they share an edge at one height.
  std::vector<int> floors;
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    const Face& f = m.faces[i];
    if (out.used[i] || f.surface.kind != SurfaceKind::Plane || f.surface.axis.z < 1 - 1e-6) continue;
    if (f.box_max.z > out.top_z - kTol) continue;  // the top
    floors.push_back(static_cast<int>(i));
  }
  std::map<int, int> group_of;
  std::vector<std::vector<int>> groups;
  for (int f : floors) {
    int g = -1;
    for (const auto& loop : m.faces[static_cast<std::size_t>(f)].loops) {
      for (const auto& e : loop.edges) {
        const int o = other_face(m, e.edge, f);
        auto it = group_of.find(o);
        if (it != group_of.end() && std::abs(m.faces[static_cast<std::size_t>(o)].box_min.z - m.faces[static_cast<std::size_t>(f)].box_min.z) < kTol) {
          if (g < 0) {
            g = it->second;
          } else if (it->second != g) {  // join two groups
            const int from = it->second;
            for (int x : groups[static_cast<std::size_t>(from)]) group_of[x] = g;
            groups[static_cast<std::size_t>(g)].insert(groups[static_cast<std::size_t>(g)].end(), groups[static_cast<std::size_t>(from)].begin(),
                                                       groups[static_cast<std::size_t>(from)].end());
            groups[static_cast<std::size_t>(from)].clear();
          }
        }
      }
    }
    if (g < 0) {
      g = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    group_of[f] = g;
    groups[static_cast<std::size_t>(g)].push_back(f);
  }

  for (const auto& group : groups) {
    if (group.empty()) continue;
    const double z = m.faces[static_cast<std::size_t>(group.front())].box_min.z;
    const auto loops = boundary_loops(m, group);
    const Chain* outer = nullptr;
    double most = 0;
    for (const auto& loop : loops) {
      const double a = area_about_z(loop);
      if (a > most) most = a, outer = &loop;
    }
    if (!outer) continue;
    if (const int ceiling = ceiling_over(m, *outer, z); ceiling >= 0) {
      out.warnings.push_back({faces_text(m, group), "a face up at z " + length_text(z) + " under " + faces_text(m, {ceiling}) +
                                                        ": the wall of a feature made from the side, not reached from above; not planned"});
      continue;
    }
    std::vector<Labelled> edges;
    std::vector<int> faces = group;
    double top = z;
    int walls = 0;
    for (const auto& b : *outer) {
      const int other = other_face(m, b.edge->edge, b.face);
      const bool wall = rises_as_wall(m, *b.edge, other, z);
      edges.push_back({b.edge, b.face, other, wall});
      if (wall) {
        ++walls;
        faces.push_back(other);
        top = std::max(top, m.faces[static_cast<std::size_t>(other)].box_max.z);
      }
    }
    const std::string source = faces_text(m, faces);
    if (walls == 0) {
      out.warnings.push_back({source, "a floor with no wall around it at z " + length_text(z) + ": not planned"});
      continue;
    }
    // Islands: inner loops that are not holes recognised already, each named by its faces. The
    // model has no boss (ISO 14649 its_boss) yet: a feature cut without its island would mill
    // the island away, so it is not planned.
    bool has_island = false;
    for (const auto& loop : loops) {
      if (&loop == outer) continue;
      std::vector<int> island;
      for (const auto& b : loop) {
        const int other = other_face(m, b.edge->edge, b.face);
        if (other >= 0 && !out.used[static_cast<std::size_t>(other)] && std::find(island.begin(), island.end(), other) == island.end()) {
          island.push_back(other);
        }
      }
      if (!island.empty()) {
        std::sort(island.begin(), island.end());
        out.warnings.push_back({faces_text(m, group), "an island (boss, " + faces_text(m, island) +
                                                          ") stands on this floor: not planned (cut without the island, "
                                                          "the island would be milled away)"});
        has_island = true;
      }
    }
    for (int f : faces) out.used[static_cast<std::size_t>(f)] = 1;
    if (has_island) continue;

    Feature f;
    f.source = source;
    f.depth = top - z;
    const auto runs = runs_of(edges);
    std::vector<const std::vector<Labelled>*> wall_runs, open_runs;
    for (const auto& r : runs) (r.front().wall ? wall_runs : open_runs).push_back(&r);

    Vec3 p1, d1, p2, d2;
    if (open_runs.empty()) {
      const auto pieces = pieces_of(edges);
      int lines = 0, arcs = 0;
      double arc_radius = -1, half_turns = 0;
      bool equal_arcs = true;
      for (const auto& p : pieces) {
        if (p.kind == CurveKind::Line) ++lines;
        else if (p.kind == CurveKind::Circle) {
          ++arcs;
          if (arc_radius < 0) arc_radius = p.radius;
          equal_arcs = equal_arcs && std::abs(p.radius - arc_radius) < kTol;
          if (std::abs(std::abs(p.sweep) - M_PI) < 1e-3) ++half_turns;
        } else {
          lines = -100;  // a free-form edge: a general outline
        }
      }
      if (lines == 2 && arcs == 2 && half_turns == 2 && equal_arcs) {  // a closed slot with round ends
        Vec3 c1, c2;
        bool first = true;
        for (const auto& p : pieces) {
          if (p.kind != CurveKind::Circle) continue;
          (first ? c1 : c2) = p.centre;
          first = false;
        }
        const Vec3 u = unit(Vec3{c2.x - c1.x, c2.y - c1.y, 0});
        f.kind = FeatureKind::Slot;
        f.outline = Outline::Rectangle;
        f.width = 2 * arc_radius;
        f.length = std::hypot(c2.x - c1.x, c2.y - c1.y);
        f.slot_ends = {SlotEnd::Radiused, SlotEnd::Radiused};
        f.placement.location = {(c1.x + c2.x) / 2, (c1.y + c2.y) / 2, top};
        set_ref(f, u);
        out.features.push_back(f);
        continue;
      }
      f.kind = FeatureKind::ClosedPocket;
      // A rectangle (its corners rounded alike, or sharp)?
      Vec3 u{1, 0, 0};
      for (const auto& p : pieces) {
        if (p.kind == CurveKind::Line) {
          u = unit(Vec3{p.end.x - p.start.x, p.end.y - p.start.y, 0});
          break;
        }
      }
      bool rectangle = lines == 4 && (arcs == 0 || (arcs == 4 && equal_arcs));
      for (const auto& p : pieces) {
        if (!rectangle) break;
        if (p.kind == CurveKind::Line) {
          const Vec3 d = unit(p.end - p.start);
          const double c = std::abs(dot(d, u));
          rectangle = c < 1e-6 || c > 1 - 1e-6;
        } else {
          rectangle = std::abs(std::abs(p.sweep) - M_PI / 2) < 1e-3;
        }
      }
      double u0, u1, v0, v1;
      extent(edges, u, u0, u1, v0, v1);
      const Vec3 v{-u.y, u.x, 0};
      const double cu = (u0 + u1) / 2, cv = (v0 + v1) / 2;
      f.placement.location = {cu * u.x + cv * v.x, cu * u.y + cv * v.y, top};
      if (rectangle) {
        f.outline = Outline::Rectangle;
        const bool along_u = u1 - u0 >= v1 - v0;
        set_ref(f, along_u ? u : v);
        f.length = along_u ? u1 - u0 : v1 - v0;
        f.width = along_u ? v1 - v0 : u1 - u0;
        f.corner_radius = arcs == 4 ? arc_radius : 0;
      } else {
        std::vector<OutlineVertex> world;
        double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
        for (const auto& l : edges) {
          for (const auto& p : l.edge->points) {
            xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x), ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
          }
        }
        f.placement.location = {(xmin + xmax) / 2, (ymin + ymax) / 2, top};
        set_ref(f, {1, 0, 0});
        f.outline = Outline::General;
        f.boundary = local(outline_of(*outer), f);
        double tightest = 1e300;
        for (const auto& p : pieces) {
          if (p.kind == CurveKind::Circle && p.sweep > 0) tightest = std::min(tightest, p.radius);
        }
        f.corner_radius = tightest < 1e300 ? tightest : 0;
      }
      out.features.push_back(f);
      continue;
    }

    if (wall_runs.size() == 2 && open_runs.size() == 2 && straight(*wall_runs[0], p1, d1) && straight(*wall_runs[1], p2, d2) &&
        dot(d1, d2) < -1 + 1e-6) {  // a through slot
      const Vec3 u = d1, v{-u.y, u.x, 0};
      const double a = dot(p1, v), b = dot(p2, v);
      double u0, u1, v0, v1;
      extent(edges, u, u0, u1, v0, v1);
      const Vec3 mid = ((a + b) / 2) * v;
      auto span = span_in(out.footprint, mid, u, (u0 + u1) / 2);
      if (!span) span = std::make_pair(u0, u1);
      f.kind = FeatureKind::Slot;
      f.outline = Outline::Rectangle;
      f.width = std::abs(a - b);
      f.length = span->second - span->first;
      f.slot_ends = {SlotEnd::Open, SlotEnd::Open};
      const double cu = (span->first + span->second) / 2;
      f.placement.location = {mid.x + cu * u.x, mid.y + cu * u.y, top};
      set_ref(f, std::abs(u.x) > 1e-9 ? (u.x > 0 ? u : -1.0 * u) : (u.y > 0 ? u : -1.0 * u));
      out.features.push_back(f);
      continue;
    }
    if (wall_runs.size() == 1 && straight(*wall_runs[0], p1, d1)) {  // a step along its wall
      const Vec3 u = d1, inward{-u.y, u.x, 0};  // from the wall over the floor, out of the part
      double u0, u1, v0, v1;
      extent(edges, u, u0, u1, v0, v1);
      const double cu = (u0 + u1) / 2, cv = (v0 + v1) / 2;
      f.kind = FeatureKind::Step;
      f.outline = Outline::Rectangle;
      f.length = u1 - u0;
      f.width = v1 - v0;
      f.placement.location = {cu * u.x + cv * inward.x, cu * u.y + cv * inward.y, top};
      // Its local y points into the part (at its wall): x = -u.
      set_ref(f, -1.0 * u);
      out.features.push_back(f);
      continue;
    }
    // An open pocket: its outline with the open edges marked.
    f.kind = FeatureKind::OpenPocket;
    f.outline = Outline::General;
    std::vector<OutlineVertex> world;
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    double tightest = 1e300;
    for (const auto& l : edges) {
      auto vertices = outline_of(Chain{{l.edge, l.face}});
      for (auto& v : vertices) v.open = !l.wall;
      world.insert(world.end(), vertices.begin(), vertices.end());
      for (const auto& p : l.edge->points) {
        xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x), ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
      }
      if (l.wall && l.edge->kind == CurveKind::Circle && l.edge->axis.z > 0) tightest = std::min(tightest, l.edge->radius);
    }
    f.placement.location = {(xmin + xmax) / 2, (ymin + ymax) / 2, top};
    set_ref(f, {1, 0, 0});
    f.boundary = local(world, f);
    f.corner_radius = tightest < 1e300 ? tightest : 0;
    f.length = xmax - xmin;
    f.width = ymax - ymin;
    out.features.push_back(f);
  }
}

}  // namespace ncbridge::part_reader::brep
