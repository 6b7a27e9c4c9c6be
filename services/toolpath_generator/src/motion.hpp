#pragma once
// Cuts at levels into 3D cutter-location moves: the approach from above, entries into material
// (a ramp along the first cut: round a loop, which is a helix on a circle, or back and forth
// along an open path; never a plunge into material), feed links between cuts that stay in the
// clearing area, retracts and rapids above the material otherwise.
#include <map>
#include <optional>
#include <vector>

#include "clearing.hpp"
#include "ncbridge/material_check/toolpath_program.hpp"
#include "ncbridge/toolpath_generator/toolpath_generator.hpp"
#include "part_model.hpp"

namespace ncbridge::toolpath_generator {

using material_check::Point3;

struct Move3 {
  enum class Kind : std::uint8_t { Rapid, Feed, Entry };
  Kind kind = Kind::Feed;
  Point3 end;
  std::optional<Point2> arc_centre;  // an arc in XY about it (z may change: a helix)
  double arc_sweep = 0;              // radians, > 0 counter-clockwise
};

struct Motion3 {
  Point3 start;
  std::vector<Move3> moves;
  bool empty() const { return moves.empty(); }
  Point3 end() const { return moves.empty() ? start : moves.back().end; }
};

class MotionBuilder {
 public:
  // `centres`: where the axis may go at a level (feed links stay in it); `safe_z`: above all
  // material, where rapids between separate cuts go.
  MotionBuilder(const PartModel& part, PolygonSet centres, double radius, double safe_z, const Options& options);

  // The cuts of one level at height z; `material_above` is where the material this level cuts
  // starts (the level above, or the feature's top).
  void level(double z, double material_above, const std::vector<Cut>& cuts);
  // A helix (whole turns about `centre`, from the current point, descending to z) as a cut.
  void helix_to(Point2 centre, double z, double sweep_per_turn, int turns);
  void feed_to(Point3 p, Move3::Kind kind = Move3::Kind::Feed);
  void rapid_to(Point3 p);
  // Above p at the safe height, down to where the feed may start, and into the material at z
  // (along `entry` when it is not air there).
  // Returns where the entry ends (a loop is then cut from there).
  Point2 approach(Point2 p, double z, double material_above, const PlanarCurve* entry);
  void retract();  // straight up to the safe height

  bool started() const { return started_; }
  Point3 position() const { return at_; }
  Motion3 take();

 private:
  void path(const PlanarCurve& curve, double z, Move3::Kind kind);
  Point2 ramp(const PlanarCurve& cut, double from_z, double to_z);
  void descend_along(const std::vector<const PlanarCurve*>& passes, double from_z, double to_z);
  bool air_at(Point2 p, double z);

  const PartModel& part_;
  PolygonSet centres_, links_;  // links: the centres and a micrometre (for links along their edge)
  std::map<double, PolygonSet> air_;  // per level: where the cutter's disk is all in air
  double radius_, safe_z_;
  const Options& options_;
  bool started_ = false;
  Point3 at_;
  Motion3 motion_;
};

}  // namespace ncbridge::toolpath_generator
