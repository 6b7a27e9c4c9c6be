// Round holes from the B-rep: the concave cylinders on one axis and radius (however many faces
// an exporter split them into) that go all the way round; what closes or opens each end (a
// plane facing into the hole: a flat bottom; a plane facing out: the hole opens there; a cone
// narrowing away: a drill point; a cone widening out: a countersink; a sphere); counterbores
// where the floor of one hole is where a smaller coaxial one opens. A shallow flat-bottomed
// one is a circular pocket.
#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "brep_recognize.hpp"

namespace ncbridge::part_reader::brep {

namespace {

struct Group {
  std::vector<int> faces;
  Vec3 origin, axis;
  double radius = 0;
  double lo = 0, hi = 0;  // along `axis` from `origin`
  double coverage = 0;
};

Vec3 canonical(Vec3 a) {
  a = unit(a);
  const bool flip = a.z < -1e-9 || (std::abs(a.z) <= 1e-9 && (a.y < -1e-9 || (std::abs(a.y) <= 1e-9 && a.x < 0)));
  return flip ? -1.0 * a : a;
}

double line_distance(Vec3 point, Vec3 origin, Vec3 axis) {
  const Vec3 d = point - origin;
  return norm(d - dot(d, axis) * axis);
}

bool coaxial(const Surface& s, const Group& g) {
  return std::abs(dot(unit(s.axis), g.axis)) > 1 - 1e-6 && line_distance(s.origin, g.origin, g.axis) < kTol;
}

enum class EndKind { Open, Flat, Conical, Spherical, Closed };

struct End {
  EndKind kind = EndKind::Open;
  int closing_face = -1;          // Flat, Conical, Spherical: the face that closes it
  std::vector<int> opening_planes;  // Open: the planes it opens into
  int countersink = -1;           // Open: a cone widening outwards here
  double apex = 0;                // Conical: where the point is, along the axis
  double tip_angle = 0;           // Conical: degrees
};

End end_of(const Model& m, const Group& g, const std::vector<int>& others, bool high) {
  End e;
  const Vec3 out = high ? g.axis : -1.0 * g.axis;
  const double at = high ? g.hi : g.lo;
  bool open = others.empty();
  for (int o : others) {
    const Surface& s = m.faces[static_cast<std::size_t>(o)].surface;
    if (s.kind == SurfaceKind::Plane && std::abs(dot(s.axis, g.axis)) > 1 - 1e-6) {
      if (dot(s.axis, out) > 0) {
        open = true;
        e.opening_planes.push_back(o);
      } else {
        e.kind = EndKind::Flat;
        e.closing_face = o;
      }
    } else if (s.kind == SurfaceKind::Cone && coaxial(s, g)) {
      const Vec3 cone_axis = unit(s.axis);
      const Vec3 apex = s.origin + (-s.radius / std::tan(s.semi_angle)) * cone_axis;
      const double where = dot(apex - g.origin, g.axis);
      if ((high && where > at + kTol) || (!high && where < at - kTol)) {
        e.kind = EndKind::Conical;
        e.closing_face = o;
        e.apex = where;
        e.tip_angle = 2 * std::abs(s.semi_angle) * 180 / M_PI;
      } else {
        open = true;
        e.countersink = o;
      }
    } else if (s.kind == SurfaceKind::Sphere && s.concave) {
      e.kind = EndKind::Spherical;
      e.closing_face = o;
    } else {
      open = true;  // it comes out through some other surface
    }
  }
  if (e.kind == EndKind::Open && !open) e.kind = EndKind::Closed;
  return e;
}

struct Hole {
  Group group;
  End low, high;
  bool enters_high = true;
  std::size_t feature = 0;
};

// A hole's closing plane holds only the hole's own circle (a drilled or milled blind bottom).
bool is_disk(const Model& m, int face, const Group& g) {
  const Face& f = m.faces[static_cast<std::size_t>(face)];
  if (f.loops.size() != 1) return false;
  for (const auto& e : f.loops.front().edges) {
    if (e.kind != CurveKind::Circle || std::abs(e.radius - g.radius) > kTol) return false;
  }
  return true;
}

}  // namespace

void recognize_holes(const Model& m, Recognized& out) {
  // Faces on one cylinder, joined where they meet or overlap along the axis (two bores of one
  // size on one axis, apart, are two holes).
  struct Piece {
    int face;
    Vec3 axis;
    double lo, hi;
  };
  std::vector<Group> groups;
  std::vector<std::vector<Piece>> pieces;
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    const Face& f = m.faces[i];
    if (f.surface.kind != SurfaceKind::Cylinder || !f.surface.concave) continue;
    const Vec3 axis = canonical(f.surface.axis);
    const double sign = dot(axis, unit(f.surface.axis)) > 0 ? 1 : -1;
    std::size_t g = groups.size();
    for (std::size_t k = 0; k < groups.size(); ++k) {
      if (std::abs(dot(axis, groups[k].axis)) > 1 - 1e-9 && line_distance(f.surface.origin, groups[k].origin, groups[k].axis) < kTol &&
          std::abs(f.surface.radius - groups[k].radius) < kTol) {
        g = k;
        break;
      }
    }
    if (g == groups.size()) {
      groups.push_back({{}, f.surface.origin, axis, f.surface.radius, 0, 0, 0});
      pieces.emplace_back();
    }
    const double base = dot(f.surface.origin - groups[g].origin, axis);
    const double a = base + sign * f.axis_min, b = base + sign * f.axis_max;
    pieces[g].push_back({static_cast<int>(i), axis, std::min(a, b), std::max(a, b)});
  }
  std::vector<Group> split;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    auto& list = pieces[g];
    std::sort(list.begin(), list.end(), [](const Piece& a, const Piece& b) { return a.lo < b.lo; });
    Group current = groups[g];
    bool open = false;
    for (const auto& p : list) {
      if (open && p.lo > current.hi + kTol) {
        split.push_back(current);
        open = false;
      }
      if (!open) {
        current.faces.clear();
        current.lo = p.lo, current.hi = p.hi, current.coverage = 0;
        open = true;
      }
      current.faces.push_back(p.face);
      current.hi = std::max(current.hi, p.hi);
      current.coverage += m.faces[static_cast<std::size_t>(p.face)].angle_span;
    }
    if (open) split.push_back(current);
  }
  groups = std::move(split);

  std::vector<Hole> holes;
  for (const auto& g : groups) {
    if (g.coverage < 2 * M_PI - 1e-3) continue;  // a partial cylinder: a pocket's corner, a slot's end
    std::set<int> in(g.faces.begin(), g.faces.end());
    std::set<int> low_faces, high_faces;
    for (int fi : g.faces) {
      for (const auto& loop : m.faces[static_cast<std::size_t>(fi)].loops) {
        for (const auto& e : loop.edges) {
          const int other = other_face(m, e.edge, fi);
          if (other < 0 || in.count(other)) continue;
          double smin = 1e300, smax = -1e300;
          for (const auto& p : e.points) {
            const double s = dot(p - g.origin, g.axis);
            smin = std::min(smin, s), smax = std::max(smax, s);
          }
          if (smin < g.lo + kTol) low_faces.insert(other);
          if (smax > g.hi - kTol) high_faces.insert(other);
        }
      }
    }
    Hole h{g, end_of(m, g, {low_faces.begin(), low_faces.end()}, false), end_of(m, g, {high_faces.begin(), high_faces.end()}, true)};
    const bool low_open = h.low.kind == EndKind::Open, high_open = h.high.kind == EndKind::Open;
    if (!low_open && !high_open) {
      out.warnings.push_back({faces_text(m, g.faces), "a cylindrical cavity closed at both ends: not a hole that can be machined"});
      continue;
    }
    if (low_open && high_open) {  // through: entered from the side that faces the spindle most
      const double up_high = g.axis.z, up_low = -g.axis.z;
      const bool flat_low = !h.low.opening_planes.empty(), flat_high = !h.high.opening_planes.empty();
      if (std::abs(up_high - up_low) > 1e-9) h.enters_high = up_high > up_low;
      else if (flat_low != flat_high) h.enters_high = flat_high;  // a drill starts on a face square to it
      else h.enters_high = g.axis.x > 1e-9 || (std::abs(g.axis.x) <= 1e-9 && g.axis.y > 0);
    } else {
      h.enters_high = high_open;
    }
    holes.push_back(h);
  }

  // Features: the hole, the circular pocket, the countersink cone in front of a hole.
  for (auto& h : holes) {
    const Group& g = h.group;
    const End& entrance = h.enters_high ? h.high : h.low;
    const End& far = h.enters_high ? h.low : h.high;
    const Vec3 out_dir = h.enters_high ? g.axis : -1.0 * g.axis;
    const double s_entry = h.enters_high ? g.hi : g.lo;
    std::vector<int> faces = g.faces;
    Feature f;
    f.kind = FeatureKind::RoundHole;
    f.diameter = 2 * g.radius;
    f.outline = Outline::Circle;
    f.placement.location = {g.origin.x + s_entry * g.axis.x, g.origin.y + s_entry * g.axis.y, g.origin.z + s_entry * g.axis.z};
    f.placement.axis = {out_dir.x, out_dir.y, out_dir.z};
    const Vec3 ref = std::abs(out_dir.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 r = unit(ref - dot(ref, out_dir) * out_dir);
    f.placement.ref_direction = {r.x, r.y, r.z};
    f.depth = g.hi - g.lo;
    switch (far.kind) {
      case EndKind::Open: f.bottom = HoleBottom::Through; break;
      case EndKind::Flat: f.bottom = HoleBottom::Flat; break;
      case EndKind::Spherical: f.bottom = HoleBottom::Spherical; f.bottom_radius = g.radius; break;
      case EndKind::Conical:
        f.bottom = HoleBottom::Conical;
        f.tip_angle = far.tip_angle;
        f.depth = std::abs(s_entry - far.apex);
        break;
      case EndKind::Closed: break;
    }
    if (far.closing_face >= 0) faces.push_back(far.closing_face);
    if (far.kind == EndKind::Flat && is_disk(m, far.closing_face, g) && f.depth < 0.5 * f.diameter && entrance.countersink < 0) {
      f.kind = FeatureKind::ClosedPocket;  // a shallow round recess: a circular pocket
    }
    for (int fi : faces) out.used[static_cast<std::size_t>(fi)] = 1;
    f.source = faces_text(m, faces);
    h.feature = out.features.size();
    out.features.push_back(f);

    if (entrance.countersink >= 0) {  // the cone in front: a countersink
      const Face& cone = m.faces[static_cast<std::size_t>(entrance.countersink)];
      const Surface& cs = cone.surface;
      const Vec3 cone_axis = unit(cs.axis);
      const double sign = dot(cone_axis, g.axis) > 0 ? 1 : -1;
      const double base = dot(cs.origin - g.origin, g.axis);
      const double s0 = base + sign * cone.axis_min, s1 = base + sign * cone.axis_max;
      const double wide = h.enters_high ? std::max(s0, s1) : std::min(s0, s1);
      const double narrow = h.enters_high ? std::min(s0, s1) : std::max(s0, s1);
      const double wide_local = (wide - base) * sign;
      Feature c = f;
      c.kind = FeatureKind::RoundHole;
      c.diameter = 2 * (cs.radius + wide_local * std::tan(cs.semi_angle));
      c.depth = std::abs(wide - narrow);
      c.bottom = HoleBottom::Conical;
      c.tip_angle = 2 * std::abs(cs.semi_angle) * 180 / M_PI;
      c.placement.location = {g.origin.x + wide * g.axis.x, g.origin.y + wide * g.axis.y, g.origin.z + wide * g.axis.z};
      c.source = faces_text(m, {entrance.countersink});
      out.used[static_cast<std::size_t>(entrance.countersink)] = 1;
      Compound compound;
      compound.kind = CompoundKind::Countersink;
      compound.source = faces_text(m, {entrance.countersink, g.faces.front()});
      compound.elements = {out.features.size(), h.feature};
      out.features[h.feature].compound = static_cast<int>(out.compounds.size());
      c.compound = static_cast<int>(out.compounds.size());
      out.features.push_back(c);
      out.compounds.push_back(compound);
    }
  }

  // Counterbores: a hole whose floor is where a smaller hole on its axis opens.
  std::vector<int> next(holes.size(), -1), previous(holes.size(), -1);
  for (std::size_t a = 0; a < holes.size(); ++a) {
    const End& far = holes[a].enters_high ? holes[a].low : holes[a].high;
    if (far.kind != EndKind::Flat) continue;
    for (std::size_t b = 0; b < holes.size(); ++b) {
      if (a == b || holes[b].group.radius >= holes[a].group.radius) continue;
      const End& entrance = holes[b].enters_high ? holes[b].high : holes[b].low;
      if (std::find(entrance.opening_planes.begin(), entrance.opening_planes.end(), far.closing_face) == entrance.opening_planes.end()) continue;
      if (std::abs(dot(holes[a].group.axis, holes[b].group.axis)) < 1 - 1e-6 ||
          line_distance(holes[b].group.origin, holes[a].group.origin, holes[a].group.axis) > kTol) {
        continue;
      }
      // One way in: both entered from the same side (a bore stepped from both ends is two).
      const Vec3 in_a = holes[a].enters_high ? holes[a].group.axis : -1.0 * holes[a].group.axis;
      const Vec3 in_b = holes[b].enters_high ? holes[b].group.axis : -1.0 * holes[b].group.axis;
      if (dot(in_a, in_b) < 0 || previous[b] >= 0) continue;
      // A shallow round recess much wider than the hole in its floor is a circular pocket with
      // a hole, not a counterbore.
      const Feature& outer = out.features[holes[a].feature];
      if (outer.depth < 0.5 * outer.diameter && outer.diameter > 2.5 * 2 * holes[b].group.radius && outer.compound < 0) {
        out.features[holes[a].feature].kind = FeatureKind::ClosedPocket;
        break;
      }
      next[a] = static_cast<int>(b);
      previous[b] = static_cast<int>(a);
      break;
    }
  }
  for (std::size_t a = 0; a < holes.size(); ++a) {
    if (previous[a] >= 0 || next[a] < 0) continue;
    Compound c;
    c.kind = CompoundKind::Counterbore;
    std::vector<int> faces;
    for (int k = static_cast<int>(a); k >= 0; k = next[static_cast<std::size_t>(k)]) {
      const std::size_t fi = holes[static_cast<std::size_t>(k)].feature;
      auto& feature = out.features[fi];
      if (feature.compound >= 0) break;  // already a countersink's hole
      feature.kind = FeatureKind::RoundHole;
      feature.compound = static_cast<int>(out.compounds.size());
      c.elements.push_back(fi);
      faces.insert(faces.end(), holes[static_cast<std::size_t>(k)].group.faces.begin(), holes[static_cast<std::size_t>(k)].group.faces.end());
    }
    if (c.elements.size() < 2) {
      for (std::size_t e : c.elements) out.features[e].compound = -1;
      continue;
    }
    c.source = faces_text(m, faces);
    out.compounds.push_back(c);
  }
}

}  // namespace ncbridge::part_reader::brep
