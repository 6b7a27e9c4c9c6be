#pragma once
// The old HEIDENHAIN pocket cycles spelled out as moves. Cycle 5 CIRCULAR POCKET, as the TNC
// manual describes it: from the starting position (the pocket centre, at the set-up clearance)
// the tool plunges to the first plunging depth (below the surface), follows a spiral out to the pocket wall at the
// milling feed, and repeats that layer by layer to the depth; at the end it returns to the
// starting position. The spiral is made of half circles whose radius grows by half the stepover
// (the overlap factor times the tool radius, MP7430) each, ending on the circle at the wall less
// the tool radius, which is milled once whole; back to the centre before the next plunge.
#include <cstdint>

#include "lowering/dialect_machine.hpp"

namespace ncbridge::interpreter::heidenhain {

struct CircularPocket {
  double cx = 0, cy = 0;       // the pocket centre (dialect frame)
  double start_z = 0;          // the starting position: the set-up clearance above the surface
  double surface_z = 0;        // the plunging depths are counted from the surface
  double bottom_z = 0;         // the pocket floor
  double plunge = 0;           // plunging depth (> 0)
  double plunge_feed = 0;      // feed for plunging (control units)
  double radius = 0;           // pocket radius
  double feed = 0;             // milling feed (control units)
  bool clockwise = false;      // DR- (else DR+)
  double tool_radius = 0;      // program units
  double overlap = 1;          // stepover = overlap * tool radius
};

void circular_pocket(lowering::DialectMachine& m, const CircularPocket& p, std::uint32_t column);

}  // namespace ncbridge::interpreter::heidenhain
