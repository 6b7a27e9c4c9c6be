// Splines in the XY plane (LinuxCNC convert_spline, convert_nurbs): G5 cubic (a Bézier from the
// current point through the control points current + IJ and end + PQ), G5.1 quadratic
// (control point current + IJ), G5.2 control points with weights collected block by block, up to
// the G5.3 that ends the curve. Each becomes one NURBS_FEED.
#include "executor.hpp"

namespace ncbridge::interpreter {

using namespace canonical;

// G5, G5.1. As in LinuxCNC neither changes the motion mode: the next block without a motion
// code moves in the mode before the spline.
void Executor::spline(const BlockCommand& b, int motion) {
  const std::uint32_t col = b.g_column[kGMotion] ? b.g_column[kGMotion] : 1;
  if (s_.comp_side != Side::Off) fail(col, "Cannot convert spline with cutter radius compensation");
  if (s_.feed_mode == FeedMode::UnitsPerMinute && s_.feed_rate == 0) fail(col, "Cannot make arc with zero feed rate");
  if (s_.feed_mode == FeedMode::InverseTime && !b.has('f')) fail(col, "F word missing with inverse time arc move");
  if (s_.plane != Plane::XY) fail(col, "Splines must be in the XY plane");
  for (char letter : {'z', 'a', 'b', 'c'}) {
    if (b.has(letter)) fail(b.col(letter), "Splines may not have motion in Z, A, B, or C");
  }
  const Pose& from = s_.position;
  NurbsFeed curve;
  curve.control_points.push_back({from.x, from.y, 1.0});
  if (motion == 51) {
    if (!b.has('i') || !b.has('j')) fail(col, "Must specify both I and J with G5.1");
    const Pose end = find_end(b, false);
    curve.control_points.push_back({from.x + b.get('i'), from.y + b.get('j'), 1.0});
    curve.control_points.push_back({end.x, end.y, 1.0});
    curve.order = 3;
    emit(curve);
    s_.position.x = end.x;
    s_.position.y = end.y;
    return;
  }
  // G5 without I and J continues the previous G5 tangentially: its first control point mirrors
  // the last one of that spline (LinuxCNC keeps -P, -Q in the cycle I, J it shares with G87).
  double first_x, first_y;
  if (!b.has('i') || !b.has('j')) {
    if (b.has('i') || b.has('j')) fail(b.has('i') ? b.col('i') : b.col('j'), "Must specify both I and J, or neither");
    first_x = from.x + s_.cycle_i;
    first_y = from.y + s_.cycle_j;
  } else {
    first_x = from.x + b.get('i');
    first_y = from.y + b.get('j');
  }
  const Pose end = find_end(b, false);
  if (!b.has('p') || !b.has('q')) fail(col, "Must specify both P and Q with G5");
  curve.control_points.push_back({first_x, first_y, 1.0});
  curve.control_points.push_back({end.x + b.get('p'), end.y + b.get('q'), 1.0});
  curve.control_points.push_back({end.x, end.y, 1.0});
  curve.order = 4;
  emit(curve);
  s_.cycle_i = -b.get('p');
  s_.cycle_j = -b.get('q');
  s_.position.x = end.x;
  s_.position.y = end.y;
}

// G5.2: one control point (X, Y with weight P) a block; the first block starts the curve at the
// current point (weight P when the block gives P without X and Y), L > 3 sets the order.
void Executor::nurbs_point(const BlockCommand& b) {
  const std::uint32_t col = b.g_column[kGMotion] ? b.g_column[kGMotion] : 1;
  if (s_.comp_side != Side::Off) fail(col, "Cannot convert NURBS with cutter radius compensation");
  if (b.has('x') != b.has('y')) fail(col, "You must specify both X and Y coordinates for Control Points");
  const double p = b.has('p') ? b.get('p') : -1.0;
  if (!b.has('x') && b.has('p') && p > 0 && !nurbs_points_.empty()) {
    fail(b.col('p'), "Can specify P without X and Y only for the first control point");
  }
  if (p <= 0 && !nurbs_points_.empty()) fail(b.has('p') ? b.col('p') : col, "Must specify positive weight P for every Control Point");
  if (s_.feed_mode == FeedMode::UnitsPerMinute && s_.feed_rate == 0) fail(col, "Cannot make a NURBS with 0 feedrate");
  if (s_.motion != 52) nurbs_points_.clear();
  if (nurbs_points_.empty()) {
    // LinuxCNC gives a first block with X and Y but no P the weight -1; that is a missing P.
    if (b.has('x') && p <= 0) fail(b.has('p') ? b.col('p') : col, "Must specify positive weight P for every Control Point");
    const bool weight_only = !b.has('x') && b.has('p') && p > 0;
    nurbs_points_.push_back({s_.position.x, s_.position.y, weight_only ? p : 1.0});
    nurbs_order_ = 3;
  }
  if (b.has('l') && b.get('l') > 3) nurbs_order_ = nearest_int(b.get('l'));
  if (b.has('x')) {
    const Pose end = find_end(b, false);
    nurbs_points_.push_back({end.x, end.y, p});
  }
  s_.motion = 52;
}

// G5.3: the curve ends; it moves to its last control point.
void Executor::nurbs_end(const BlockCommand& b) {
  const std::uint32_t col = b.g_column[kGNonModal];
  if (s_.motion != 52) fail(col, "Cannot use G5.3 without G5.2 first");
  if (nurbs_points_.size() < static_cast<std::size_t>(nurbs_order_)) {
    fail(col, "You must specify a number of control points at least equal to the order L = " + std::to_string(nurbs_order_));
  }
  s_.position.x = nurbs_points_.back().x;
  s_.position.y = nurbs_points_.back().y;
  emit(NurbsFeed{nurbs_points_, nurbs_order_});
  nurbs_points_.clear();
  s_.motion = -1;
}

}  // namespace ncbridge::interpreter
