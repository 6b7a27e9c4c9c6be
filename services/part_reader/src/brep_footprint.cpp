// The part's outline from above (the outer loop of the faces it stands on), its top and bottom
// heights, and the faces no feature explains that face another way than up.
#include <algorithm>
#include <cmath>

#include "brep_recognize.hpp"

namespace ncbridge::part_reader::brep {

namespace {

std::vector<OutlineVertex> reversed(const std::vector<OutlineVertex>& v) {
  std::vector<OutlineVertex> out;
  const std::size_t n = v.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (n - k) % n;  // v[0], v[n-1], ..., v[1]
    OutlineVertex o = v[i];
    const OutlineVertex& leaving = v[(i + n - 1) % n];  // the edge that now leaves o is the old edge i-1 -> i
    o.bulge = -leaving.bulge;
    o.open = leaving.open;
    out.push_back(o);
  }
  return out;
}

}  // namespace

void recognize_footprint(const Model& m, Recognized& out) {
  out.bottom_z = m.box_min.z;
  out.top_z = m.box_max.z;
  double top = -1e300;
  std::vector<int> bottom;
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    const Face& f = m.faces[i];
    if (f.surface.kind != SurfaceKind::Plane) continue;
    if (f.surface.axis.z > 1 - 1e-6) top = std::max(top, f.box_max.z);
    if (f.surface.axis.z < -1 + 1e-6 && std::abs(f.box_min.z - out.bottom_z) < kTol) bottom.push_back(static_cast<int>(i));
  }
  if (top > -1e300) out.top_z = top;
  if (bottom.empty()) {
    out.warnings.push_back({"", "the part has no flat bottom face: no outline from above (no outside profile, no facing)"});
    return;
  }
  const auto loops = boundary_loops(m, bottom);
  const Chain* outer = nullptr;
  double most = 0;
  for (const auto& loop : loops) {
    const double a = area_about_z(loop);  // seen from above, the bottom's outer loop runs clockwise
    if (a < most) most = a, outer = &loop;
  }
  if (!outer) return;
  out.footprint = reversed(outline_of(*outer));
}

void report_other_faces(const Model& m, Recognized& out) {
  std::vector<int> down, inclined;
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    const Face& f = m.faces[i];
    if (out.used[i] || f.surface.kind != SurfaceKind::Plane) continue;
    const double nz = f.surface.axis.z;
    if (nz < -1 + 1e-6 && f.box_min.z > out.bottom_z + kTol) down.push_back(static_cast<int>(i));
    else if (std::abs(nz) > 1e-6 && std::abs(std::abs(nz) - 1) > 1e-6) inclined.push_back(static_cast<int>(i));
  }
  if (!down.empty()) {
    out.warnings.push_back({faces_text(m, down), "faces down above the part's bottom (undercuts, or features made from below): "
                                                 "need a setup with -z up (--setup -z); not planned"});
  }
  if (!inclined.empty()) {
    out.warnings.push_back({faces_text(m, inclined), "inclined planar faces: need a tilted setup; not planned"});
  }
}

}  // namespace ncbridge::part_reader::brep
