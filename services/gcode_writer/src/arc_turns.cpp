#include "arc_turns.hpp"

#include <cmath>
#include <numbers>

namespace ncbridge::gcode_writer {

using namespace canonical;

std::vector<ArcFeed> split_turns(const Pose& start, const ArcFeed& arc, Plane plane) {
  const int turns = arc.rotation < 0 ? -arc.rotation : arc.rotation;
  if (turns <= 1) return {arc};
  double s1 = start.x, s2 = start.y, sn = start.z;
  if (plane == Plane::YZ) {
    s1 = start.y; s2 = start.z; sn = start.x;
  } else if (plane == Plane::XZ) {
    s1 = start.z; s2 = start.x; sn = start.y;
  }
  const double two_pi = 2 * std::numbers::pi;
  const double a0 = std::atan2(s2 - arc.second_axis, s1 - arc.first_axis);
  const double a1 = std::atan2(arc.second_end - arc.second_axis, arc.first_end - arc.first_axis);
  double base = arc.rotation > 0 ? a1 - a0 : a0 - a1;
  while (base <= 1e-12) base += two_pi;
  while (base > two_pi + 1e-12) base -= two_pi;
  const double total = base + two_pi * (turns - 1);
  std::vector<ArcFeed> pieces;
  for (int k = 1; k < turns; ++k) {
    ArcFeed piece = arc;
    piece.rotation = arc.rotation < 0 ? -1 : 1;
    piece.first_end = s1;
    piece.second_end = s2;
    piece.axis_end_point = sn + (arc.axis_end_point - sn) * (two_pi * k / total);
    piece.a = start.a; piece.b = start.b; piece.c = start.c;
    piece.u = start.u; piece.v = start.v; piece.w = start.w;
    pieces.push_back(piece);
  }
  ArcFeed last = arc;
  last.rotation = arc.rotation < 0 ? -1 : 1;
  pieces.push_back(last);
  return pieces;
}

}  // namespace ncbridge::gcode_writer
