#pragma once
// The recogniser's input: CC1 machining workingsteps as explicit cutter-location toolpaths.
// Coordinates are in the program frame (active work offset), millimetres; z is the tool tip.
// The adapter from the CC1 model (or a canonical-call segmenter) fills these values; the
// recogniser never sees program text or comments.
#include <cstdint>
#include <optional>
#include <vector>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::feature_recognizer {

struct Point3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Point3&, const Point3&) = default;
};

enum class MoveKind : std::uint8_t { Rapid, Linear, Arc };

// One cutter-location move from the previous position to `end`. Arcs lie in the XY plane
// (G17); z changes linearly along an arc (a helix). Arcs in other planes are given as chords.
struct Move {
  MoveKind kind = MoveKind::Linear;
  Point3 end;
  double center_x = 0, center_y = 0;  // Arc only
  bool clockwise = false;             // Arc only
  int turns = 1;                      // Arc only: 1 = up to one turn, n = n-1 extra full turns
  std::uint32_t source_line = 0;      // for error messages; 0 = unknown
};

struct ToolpathWorkingstep {
  setup::Tool tool;                // type and diameter drive the recognition
  double feed = 0;                 // mm/min, the cutting feed (0 = unknown)
  double spindle_rpm = 0;          // 0 = unknown
  Point3 start;                    // tool position before the first move
  std::vector<Move> moves;         // in order, rapids included
  std::optional<canonical::CycleTag> cycle;  // set when a canned cycle made this workingstep
};

}  // namespace ncbridge::feature_recognizer
