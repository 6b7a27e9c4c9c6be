#pragma once
// Cutter-location motion to simulate: per workingstep, the tool's shape and its moves (tool tip
// positions, program frame, mm). Filled from an ISO 14649 model (explicit toolpaths of any
// operation, RAPID_MOVEMENTs, and the motion a drilling-family operation on a ROUND_HOLE
// implies) or by hand (tests, other readers).
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/material_check/cutter_shape.hpp"
#include "ncbridge/material_check/planar_curve.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::material_check {

struct Point3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Point3&, const Point3&) = default;
};

// One move from the previous position to `end`: a rapid (must not touch material) or a feed;
// a feed may be an arc in the XY plane about `arc_centre` sweeping `arc_sweep` radians (> 0
// counter-clockwise, up to whole turns), with z changing linearly along it (a helix).
struct Motion {
  bool rapid = false;
  Point3 end;
  std::optional<Point2> arc_centre;
  double arc_sweep = 0;
};

struct ToolRun {
  std::string workingstep;   // the workingstep (or rapid movement) id, for reports
  std::string tool;          // the tool's id
  CutterShape cutter;
  bool drilling = false;     // a drilling-family operation: its tool cuts along its axis
  Point3 start;              // where the tool is before the first motion
  std::vector<Motion> motions;
};

struct ToolpathProgram {
  std::vector<ToolRun> runs;
};

// The motion of a CC1 (or CC2 with toolpaths) model in workplan order. RAPID_MOVEMENTs and
// CONNECT / NON_CONTACT trajectories are rapids (with the next workingstep's tool, which is
// loaded before the move); XY arcs stay arcs, arcs in other planes become chords within
// 0.001 mm. A drilling operation on a ROUND_HOLE without an explicit toolpath is a rapid to its
// retract plane over the hole, a feed to its cutting depth (the hole's depth when unset) and a
// rapid back. Operations without toolpath or implied motion add nothing. `start` is where the
// tool is before the program (default: the setup's security plane above the first move).
ToolpathProgram program_from_stepnc(const stepnc::Project& project, std::optional<Point3> start = std::nullopt);

}  // namespace ncbridge::material_check
