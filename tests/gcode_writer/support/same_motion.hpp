#pragma once
// "The same motion" of two canonical listings (`ncbridge canon` / rs274 format), as the round
// trip of a written program is judged:
//  - comments and operator messages, ON_RESET and FINISH (tape markers) and the N column aside;
//  - state calls (units, offsets, tool length, feed, speed, spindle, coolant, path mode, plane,
//    overrides, tool selection) are not compared as calls but as the state they set: each
//    action is compared together with the state it depends on (moves: frame, spindle and
//    coolant, selected tool; feed moves and arcs also feed, overrides and path mode (a rapid is
//    positioning: how a control blends it is its own business), arcs the plane; dwells and
//    stops the spindle and coolant). A call that sets what is already set
//    changes nothing; lengths of offsets and feeds compare in mm (a SET_FEED_RATE is in the
//    units of its time);
//  - a move that does not move is dropped (posts leave out blocks that repeat the position);
//  - an arc of n turns equals n arcs of one turn, the helix rising evenly (Fanuc and Mach3
//    arcs turn at most once);
//  - numbers agree within `tolerance` (both listings print 4 decimals).
// Canned cycles are not named in listings: a cycle compares by the motion it makes.
#include <cstddef>
#include <string>
#include <string_view>

namespace ncbridge::testing {

struct MotionComparison {
  bool equal = true;
  std::size_t actions = 0;  // actions compared
  std::string report;       // where they first differ
};

MotionComparison compare_motion(std::string_view expected_listing, std::string_view actual_listing,
                                double tolerance = 1e-4);

}  // namespace ncbridge::testing
