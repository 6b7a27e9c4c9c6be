#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "brep_recognize.hpp"

namespace ncbridge::part_reader::brep {

namespace {

constexpr double kSnap = 1e-4;  // mm: edge ends that are one point

bool same_point(Vec3 a, Vec3 b) { return norm(a - b) < kSnap; }

}  // namespace

std::vector<Chain> boundary_loops(const Model& model, const std::vector<int>& faces) {
  const std::set<int> in(faces.begin(), faces.end());
  std::vector<BoundaryEdge> pool;
  for (int f : faces) {
    for (const auto& loop : model.faces[static_cast<std::size_t>(f)].loops) {
      for (const auto& e : loop.edges) {
        const int other = other_face(model, e.edge, f);
        if (other >= 0 && in.count(other)) continue;  // inside the set (or a seam)
        pool.push_back({&e, f});
      }
    }
  }
  std::vector<Chain> loops;
  std::vector<char> taken(pool.size(), 0);
  for (std::size_t s = 0; s < pool.size(); ++s) {
    if (taken[s]) continue;
    Chain chain{pool[s]};
    taken[s] = 1;
    while (!same_point(chain.back().edge->end, chain.front().edge->start)) {
      std::size_t next = pool.size();
      for (std::size_t k = 0; k < pool.size(); ++k) {
        if (!taken[k] && same_point(pool[k].edge->start, chain.back().edge->end)) {
          next = k;
          break;
        }
      }
      if (next == pool.size()) break;  // open: a broken model; keep what joins
      taken[next] = 1;
      chain.push_back(pool[next]);
    }
    loops.push_back(std::move(chain));
  }
  return loops;
}

double area_about_z(const Chain& chain) {
  double a = 0;
  for (const auto& b : chain) {
    const auto& p = b.edge->points;
    for (std::size_t i = 0; i + 1 < p.size(); ++i) a += p[i].x * p[i + 1].y - p[i + 1].x * p[i].y;
  }
  return a;
}

std::vector<OutlineVertex> outline_of(const Chain& chain) {
  std::vector<OutlineVertex> out;
  for (const auto& b : chain) {
    const OrientedEdge& e = *b.edge;
    const bool arc_about_z = e.kind == CurveKind::Circle && std::abs(std::abs(e.axis.z) - 1) < 1e-9;
    if (e.kind == CurveKind::Line || e.points.size() < 3) {
      out.push_back({e.start.x, e.start.y, 0});
      continue;
    }
    if (arc_about_z) {
      const double signed_sweep = e.axis.z > 0 ? e.sweep : -e.sweep;
      // Arcs of more than half a turn in two pieces (a bulge stays finite).
      if (std::abs(e.sweep) <= M_PI - 1e-9) {
        out.push_back({e.start.x, e.start.y, std::tan(signed_sweep / 4)});
        continue;
      }
      const double half = signed_sweep / 2;
      const double dx = e.start.x - e.centre.x, dy = e.start.y - e.centre.y;
      out.push_back({e.start.x, e.start.y, std::tan(half / 4)});
      out.push_back({e.centre.x + dx * std::cos(half) - dy * std::sin(half), e.centre.y + dx * std::sin(half) + dy * std::cos(half),
                     std::tan(half / 4)});
      continue;
    }
    for (std::size_t i = 0; i + 1 < e.points.size(); ++i) out.push_back({e.points[i].x, e.points[i].y, 0});
  }
  return out;
}

std::string faces_text(const Model& model, std::vector<int> faces) {
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  std::string text = faces.size() == 1 ? "face " : "faces ";
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (i > 0) text += ", ";
    text += std::to_string(model.faces[static_cast<std::size_t>(faces[i])].index);
  }
  return text;
}

std::string length_text(double mm) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", std::abs(mm) < 5e-7 ? 0.0 : mm);
  return buf;
}

}  // namespace ncbridge::part_reader::brep
