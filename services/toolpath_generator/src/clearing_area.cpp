#include <cmath>
#include <variant>

#include "clearing.hpp"

namespace ncbridge::toolpath_generator {

ClearingArea clearing_area(const PartModel& part, const ShapedFeature& f, double floor_z, double radius, double allowance,
                           double run_out) {
  ClearingArea c;
  c.area = f.area;
  c.radius = radius;
  c.offset = radius + allowance;
  c.run_out = run_out;
  // Far enough around the area for links and lead-ins from outside a stock allowance.
  const double near = 4 * c.offset + run_out + 2;
  const PolygonSet free = part.free_space(f, floor_z, near);
  // A face takes off everything of the stock's top around it that the part does not keep (the
  // stock allowance about it too), running out past the stock's edges.
  if (std::holds_alternative<stepnc::PlanarFace>(*f.cc2)) {
    const auto& s = part.stock();
    c.area = c.area.united(free.intersected(PolygonSet::rectangle({s.min[0], s.min[1], s.max[0], s.max[1]})));
  }
  // A hair more than the cutter: floating-point noise never takes it into a wall.
  c.centres = free.offset(-(c.offset + 1e-4), kArcTolerance);
  if (c.centres.empty()) return c;
  c.tight = c.centres.intersected(c.area.offset(run_out - radius, kArcTolerance));
  c.loose = c.centres.intersected(c.area.offset(radius - run_out, kArcTolerance));
  c.passes = c.centres.intersected(c.area.offset(radius + run_out, kArcTolerance));
  // Open when the cutter, where it would go, reaches out of the stock (a closed pocket near the
  // stock's edge is not).
  c.open = !c.loose.offset(radius + run_out, kArcTolerance).intersected(part.outside_stock()).empty();
  return c;
}

PolygonSet to_cut(const ClearingArea& c, const PolygonSet& cleared) {
  if (c.centres.empty()) return {};
  const PolygonSet reach = c.centres.offset(c.radius, kArcTolerance);
  return without_slivers(c.area.intersected(reach).minus(cleared), 0.004);
}

bool counter_clockwise_for(const LoopSense& sense, bool hole_ring) {
  if (sense.counter_clockwise) return *sense.counter_clockwise;
  // Climb milling with a clockwise (M3) spindle runs a pocket's wall counter-clockwise and a
  // profile's part clockwise.
  const bool pocket_ccw = sense.climb == sense.spindle_clockwise;
  return hole_ring ? !pocket_ccw : pocket_ccw;
}

}  // namespace ncbridge::toolpath_generator
