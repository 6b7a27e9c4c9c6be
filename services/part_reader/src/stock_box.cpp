#include <algorithm>
#include <cmath>

#include "ncbridge/part_reader/part.hpp"

namespace ncbridge::part_reader {

Box bounding_box(const PartStock& stock) {
  const auto& p = stock.placement;
  const stepnc::Direction z = p.axis, x = p.ref_direction;
  const stepnc::Direction y{z.y * x.z - z.z * x.y, z.z * x.x - z.x * x.z, z.x * x.y - z.y * x.x};
  Box box{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
  auto add = [&](double px, double py, double pz, double half_x, double half_y, double half_z) {
    const double c[3] = {px, py, pz}, h[3] = {half_x, half_y, half_z};
    for (int i = 0; i < 3; ++i) {
      box.min[i] = std::min(box.min[i], c[i] - h[i]);
      box.max[i] = std::max(box.max[i], c[i] + h[i]);
    }
  };
  if (stock.shape == StockShape::Block) {
    for (int i = 0; i < 8; ++i) {
      const double a = (i & 1) ? stock.length : 0, b = (i & 2) ? stock.width : 0, c = (i & 4) ? stock.height : 0;
      add(p.location.x + a * x.x + b * y.x + c * z.x, p.location.y + a * x.y + b * y.y + c * z.y,
          p.location.z + a * x.z + b * y.z + c * z.z, 0, 0, 0);
    }
    return box;
  }
  // A cylinder: both end discs, each reaching r * sqrt(1 - axis_i^2) along axis i.
  const double r = stock.diameter / 2;
  const double e[3] = {r * std::sqrt(std::max(0.0, 1 - z.x * z.x)), r * std::sqrt(std::max(0.0, 1 - z.y * z.y)),
                       r * std::sqrt(std::max(0.0, 1 - z.z * z.z))};
  add(p.location.x, p.location.y, p.location.z, e[0], e[1], e[2]);
  add(p.location.x + stock.length * z.x, p.location.y + stock.length * z.y, p.location.z + stock.length * z.z, e[0], e[1], e[2]);
  return box;
}

}  // namespace ncbridge::part_reader
