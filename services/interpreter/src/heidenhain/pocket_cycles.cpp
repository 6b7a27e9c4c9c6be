#include "heidenhain/pocket_cycles.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace ncbridge::interpreter::heidenhain {

using lowering::NeutralBlock;

void circular_pocket(lowering::DialectMachine& m, const CircularPocket& p, std::uint32_t column) {
  const double wall = p.radius - p.tool_radius;  // radius of the tool centre's last circle
  if (wall <= 1e-9) m.fail(column, "Cycle 5: the tool (radius " + std::to_string(p.tool_radius) +
                                       ") is not smaller than the pocket radius " + std::to_string(p.radius));
  if (p.plunge <= 0) m.fail(column, "Cycle 5 needs a plunging depth");
  if (p.plunge_feed <= 0 || p.feed <= 0) m.fail(column, "Cycle 5 needs the plunging and milling feeds");
  const double step = p.overlap * p.tool_radius;
  if (step <= 1e-9) m.fail(column, "Cycle 5: no stepover (the tool's radius or the overlap factor is 0)");
  const double depth = p.surface_z - p.bottom_z;
  const int layers = std::max(1, static_cast<int>(std::ceil(depth / p.plunge - 1e-9)));
  auto run = [&](NeutralBlock& nb) {
    if (m.execute(nb)) m.fail(column, "Cycle 5 ended the program");
    nb.clear();
  };
  NeutralBlock nb;
  for (int layer = 1; layer <= layers; ++layer) {
    const double z = std::max(p.bottom_z, p.surface_z - layer * p.plunge);
    nb.g(1, column);
    nb.add('f', p.plunge_feed, column);
    m.put_axes(nb, std::nullopt, std::nullopt, z, column);
    run(nb);
    // the spiral: half circles from x_k to x_(k+1) = -(|x_k| + step/2) sign-alternating, about
    // their midpoint, until the wall; then the wall circle whole
    double x = 0;
    int side = -1;  // the first half circle goes towards -X
    bool first = true;
    while (std::fabs(x) < wall - 1e-9) {
      const double next_abs = std::min(wall, std::fabs(x) + step / 2.0);
      const double next = side * next_abs;
      m.put_xy_arc(nb, p.clockwise, p.cx + next, p.cy, std::nullopt, p.cx + (x + next) / 2.0, p.cy, column);
      if (first) {
        nb.add('f', p.feed, column);
        first = false;
      }
      run(nb);
      x = next;
      side = -side;
    }
    m.put_xy_arc(nb, p.clockwise, p.cx + x, p.cy, std::nullopt, p.cx, p.cy, column);
    run(nb);
    nb.g(1, column);
    m.put_axes(nb, p.cx, p.cy, std::nullopt, column);
    run(nb);
  }
  nb.g(0, column);
  m.put_axes(nb, std::nullopt, std::nullopt, p.start_z, column);
  run(nb);
}

}  // namespace ncbridge::interpreter::heidenhain
