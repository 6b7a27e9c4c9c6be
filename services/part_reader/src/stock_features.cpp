// The features a B-rep part needs because of its stock: the top face milled down to the part's
// top, and the outside profile where the stock reaches beyond the part's outline.
#include <algorithm>
#include <cmath>

#include "ncbridge/part_reader/part.hpp"

namespace ncbridge::part_reader {

namespace {

constexpr double kTol = 1e-3;

// Does every edge of the outline lie on the stock's sides?
bool outline_is_stock(const std::vector<OutlineVertex>& outline, const Box& stock) {
  const std::size_t n = outline.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = outline[i];
    const auto& b = outline[(i + 1) % n];
    if (a.bulge != 0) return false;
    const bool on_x = (std::abs(a.x - stock.min[0]) < kTol && std::abs(b.x - stock.min[0]) < kTol) ||
                      (std::abs(a.x - stock.max[0]) < kTol && std::abs(b.x - stock.max[0]) < kTol);
    const bool on_y = (std::abs(a.y - stock.min[1]) < kTol && std::abs(b.y - stock.min[1]) < kTol) ||
                      (std::abs(a.y - stock.max[1]) < kTol && std::abs(b.y - stock.max[1]) < kTol);
    if (!on_x && !on_y) return false;
  }
  return true;
}

}  // namespace

void add_stock_features(Part& part, const Box& stock) {
  if (part.footprint.size() < 2) return;
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  const std::size_t n = part.footprint.size();
  for (std::size_t i = 0; i < n; ++i) {  // the outline's box, arcs included
    const auto& a = part.footprint[i];
    const auto& b = part.footprint[(i + 1) % n];
    xmin = std::min(xmin, a.x), xmax = std::max(xmax, a.x), ymin = std::min(ymin, a.y), ymax = std::max(ymax, a.y);
    if (a.bulge == 0) continue;
    const double chord = std::hypot(b.x - a.x, b.y - a.y);
    const double d = chord * (1 - a.bulge * a.bulge) / (4 * a.bulge);
    const double cx = (a.x + b.x) / 2 - (b.y - a.y) / chord * d, cy = (a.y + b.y) / 2 + (b.x - a.x) / chord * d;
    const double r = std::hypot(a.x - cx, a.y - cy), t0 = std::atan2(a.y - cy, a.x - cx), sweep = 4 * std::atan(a.bulge);
    for (int k = 1; k <= 64; ++k) {
      const double t = t0 + sweep * k / 64;
      xmin = std::min(xmin, cx + r * std::cos(t)), xmax = std::max(xmax, cx + r * std::cos(t));
      ymin = std::min(ymin, cy + r * std::sin(t)), ymax = std::max(ymax, cy + r * std::sin(t));
    }
  }
  const double cx = (xmin + xmax) / 2, cy = (ymin + ymax) / 2;
  std::vector<Feature> added;
  if (stock.max[2] > part.top_z + kTol) {
    Feature face;
    face.kind = FeatureKind::PlanarFace;
    face.source = "the top face";
    face.outline = Outline::Rectangle;
    face.length = xmax - xmin;
    face.width = ymax - ymin;
    face.depth = stock.max[2] - part.top_z;
    face.placement.location = {cx, cy, stock.max[2]};
    added.push_back(face);
  }
  if (!outline_is_stock(part.footprint, stock)) {
    Feature profile;
    profile.kind = FeatureKind::GeneralOutsideProfile;
    profile.source = "the part's outline";
    profile.outline = Outline::General;
    profile.placement.location = {cx, cy, part.top_z};
    for (auto v : part.footprint) {
      v.x -= cx;
      v.y -= cy;
      v.open = false;
      profile.boundary.push_back(v);
    }
    profile.depth = part.top_z - part.bottom_z;
    profile.length = xmax - xmin;
    profile.width = ymax - ymin;
    added.push_back(profile);
  }
  // The compounds' element indices move with the features.
  for (auto& c : part.compounds) {
    for (auto& e : c.elements) e += added.size();
  }
  part.features.insert(part.features.begin(), added.begin(), added.end());
}

}  // namespace ncbridge::part_reader
