#pragma once
// A part feature's geometry in the setup frame's XY plane: its frame, its outline (corners with
// bulges, counter-clockwise), which sides of the part it opens to, and the tightest corner a
// cutter must fit.
#include <vector>

#include "ncbridge/part_reader/part.hpp"
#include "ncbridge/setup/stock.hpp"

namespace ncbridge::process_planner {

struct XY {
  double x = 0, y = 0;
};

// The feature's local frame in the setup XY plane: origin at its placement, x along its
// ref direction.
struct LocalFrame {
  double ox = 0, oy = 0, oz = 0;
  double cx = 1, sx = 0;  // the local x axis (cos, sin)
  XY to_world(double lx, double ly) const { return {ox + lx * cx - ly * sx, oy + lx * sx + ly * cx}; }
  XY to_local(double wx, double wy) const {
    const double dx = wx - ox, dy = wy - oy;
    return {dx * cx + dy * sx, -dx * sx + dy * cx};
  }
};
LocalFrame frame_of(const part_reader::Feature& f);

// The outline in the feature's local frame (rectangles with their corner radii as arcs,
// circles as two half arcs), counter-clockwise; open flags as the feature gives them.
std::vector<part_reader::OutlineVertex> local_outline(const part_reader::Feature& f);

// The smallest radius of the corners a cutter going round the outline from inside (pockets,
// slots: `inside` true) or outside (profiles) must fit; 0 for a sharp corner, a large number
// when there is none.
double tightest_corner(const std::vector<part_reader::OutlineVertex>& outline, bool inside);

// The narrowest width of the feature's outline (of its bounding box in its local frame).
double narrowest(const part_reader::Feature& f);

// Points along a local outline, arcs cut into chords of at most `step` degrees.
std::vector<XY> outline_points(const std::vector<part_reader::OutlineVertex>& outline, double step = 10);

}  // namespace ncbridge::process_planner
