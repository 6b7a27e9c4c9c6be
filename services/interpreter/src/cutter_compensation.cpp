#include "cutter_compensation.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

// The arithmetic mirrors LinuxCNC's, including where it mixes long double constants (M_PIl)
// into double expressions, so the printed results agree to the last digit (and sign of zero).
namespace ncbridge::interpreter {

namespace {

using canonical::ArcFeed;
using canonical::Call;
using canonical::Pose;
using canonical::Side;
using canonical::Source;

constexpr long double kPi = 3.141592653589793238462643383279502884L;
constexpr long double kHalfPi = kPi / 2;
constexpr double kConcaveCorner = 0.05;     // radians: below this a corner is straight on
constexpr double kEqual = 0.0001;           // LinuxCNC TOLERANCE_EQUAL
constexpr double kMismatchedRadii = 0.01;   // when moving a queued arc's end point
constexpr double kSweepSlack = 0.001;       // radians

// The tool is on the inside of an arc turning towards its side.
bool tool_inside_arc(Side side, int rotation) {
  return (side == Side::Left && rotation > 0) || (side == Side::Right && rotation < 0);
}

// Signed sweep in radians from (x1, y1) to (x2, y2) around the centre; `rotation` as ARC_FEED.
double sweep(double x1, double y1, double center_x, double center_y, int rotation, double x2,
             double y2) {
  if (rotation == 0) return 0.0;
  double alpha = std::atan2(y1 - center_y, x1 - center_x);
  double beta = std::atan2(y2 - center_y, x2 - center_x);
  if (rotation > 0) {
    if (beta <= alpha) beta = beta + 2 * kPi;
    return (beta - alpha) + (rotation - 1) * (2 * kPi);
  }
  if (alpha <= beta) alpha = alpha + 2 * kPi;
  return (beta - alpha) + (rotation + 1) * (2 * kPi);
}

// The calls LinuxCNC holds back behind a pending compensated move (interp_queue.cc);
// everything else reaches the machine at once, ahead of the pending move.
bool waits_for_pending_move(const canonical::Data& data) {
  return std::holds_alternative<canonical::SetFeedRate>(data) ||
         std::holds_alternative<canonical::Dwell>(data) ||
         std::holds_alternative<canonical::SetFeedMode>(data) ||
         std::holds_alternative<canonical::MistOn>(data) ||
         std::holds_alternative<canonical::MistOff>(data) ||
         std::holds_alternative<canonical::FloodOn>(data) ||
         std::holds_alternative<canonical::FloodOff>(data) ||
         std::holds_alternative<canonical::StartSpindleClockwise>(data) ||
         std::holds_alternative<canonical::StartSpindleCounterclockwise>(data) ||
         std::holds_alternative<canonical::StopSpindleTurning>(data) ||
         std::holds_alternative<canonical::SetSpindleMode>(data) ||
         std::holds_alternative<canonical::SetSpindleSpeed>(data) ||
         std::holds_alternative<canonical::OrientSpindle>(data) ||
         std::holds_alternative<canonical::Comment>(data);
}

Pose with_xy(Pose pose, double x, double y) {
  pose.x = x;
  pose.y = y;
  return pose;
}

Pose end_of(const ArcFeed& arc) {
  return Pose{arc.first_end, arc.second_end, arc.axis_end_point, arc.a, arc.b, arc.c,
              arc.u, arc.v, arc.w};
}

ArcFeed arc_to(double x, double y, double center_x, double center_y, int rotation, double z,
               const Pose& axes) {
  return ArcFeed{x, y, center_x, center_y, rotation, z, axes.a, axes.b, axes.c,
                 axes.u, axes.v, axes.w};
}

void scale_pose(Pose& pose, double factor) {
  pose.x *= factor;
  pose.y *= factor;
  pose.z *= factor;
  pose.u *= factor;
  pose.v *= factor;
  pose.w *= factor;
}

}  // namespace

CutterCompensation::CutterCompensation(canonical::Sink& out, Locate locate, canonical::Units units)
    : out_(out), locate_(std::move(locate)), units_(units) {}

void CutterCompensation::set_position(const Pose& position) {
  current_ = position;
  programmed_ = position;
}

void CutterCompensation::set_length_units(canonical::Units units) {
  if (units == units_) return;
  scale(units == canonical::Units::Millimeters ? 25.4 : 1.0 / 25.4);
  units_ = units;
}

void CutterCompensation::start(Side side, double radius, const Source& source) {
  if (side == Side::Off) throw std::invalid_argument("CutterCompensation::start needs a side");
  if (active()) fail(source, "Cannot turn cutter radius comp on when on");
  if (radius < 0.0) {
    radius = -radius;
    side = side == Side::Right ? Side::Left : Side::Right;
  }
  other(Call{canonical::Comment{side == Side::Right
                                    ? "interpreter: cutter radius compensation on right"
                                    : "interpreter: cutter radius compensation on left"},
             source, std::nullopt});
  side_ = side;
  radius_ = radius;
  first_move_ = true;
}

void CutterCompensation::stop(const Source& source) {
  other(Call{canonical::Comment{"interpreter: cutter radius compensation off"}, source, std::nullopt});
  if (active() && radius_ > 0.0) {
    move_endpoint_and_flush(current_.x, current_.y, source);
    dequeue();
  }
  side_ = Side::Off;
  first_move_ = true;
}

void CutterCompensation::reset() {
  queue_.clear();
  endpoint_valid_ = false;
  side_ = Side::Off;
  first_move_ = true;
}

void CutterCompensation::flush() {
  if (queue_.empty()) return;
  move_endpoint_and_flush(current_.x, current_.y, queue_.front().call.source);
  dequeue();
}

void CutterCompensation::other(const Call& call) {
  if (const auto* units = std::get_if<canonical::UseLengthUnits>(&call.data)) {
    set_length_units(units->units);
  } else if (!queue_.empty() && waits_for_pending_move(call.data)) {
    queue_.push_back(Queued{call});
    return;
  }
  emit(call);
}

// ---- Straight moves (LinuxCNC convert_straight_comp1 / comp2)

void CutterCompensation::straight(bool feed, const Pose& programmed_end, const Source& source) {
  if (!active() || radius_ <= 0.0) {
    if (feed) emit(Call{canonical::StraightFeed{programmed_end}, source, std::nullopt});
    else emit(Call{canonical::StraightTraverse{programmed_end}, source, std::nullopt});
    current_ = programmed_end;
    programmed_ = programmed_end;
    return;
  }
  if (first_move_) straight_first(feed, programmed_end, source);
  else straight_next(feed, programmed_end, source);
}

// Entry move: a line from the current point tangent to the tool circle at the programmed end.
void CutterCompensation::straight_first(bool feed, const Pose& end, const Source& source) {
  const double cx = current_.x;
  const double cy = current_.y;
  const double px = end.x;
  const double py = end.y;
  if (std::hypot(px - cx, py - cy) <= radius_)
    fail(source, "Length of cutter compensation entry move is not greater than the tool radius");

  const double alpha = std::atan2(py - cy, px - cx) + (side_ == Side::Left ? kPi / 2. : -kPi / 2.);
  const double end_x = px + radius_ * std::cos(alpha);
  const double end_y = py + radius_ * std::sin(alpha);

  set_endpoint(cx, cy);
  // LinuxCNC records the normal, not the motion, as this move's direction.
  enqueue_straight(feed, std::cos(alpha), std::sin(alpha), with_xy(end, end_x, end_y), source);
  first_move_ = false;
  current_ = with_xy(end, end_x, end_y);
  programmed_ = end;
}

void CutterCompensation::straight_next(bool feed, const Pose& end, const Source& source) {
  const double cx = current_.x;
  const double cy = current_.y;
  const double cz = current_.z;
  const double opx = programmed_.x;
  const double opy = programmed_.y;
  const double px = end.x;
  const double py = end.y;

  if (py == opy && px == opx) {  // no motion in the plane: stay beside the programmed point
    enqueue_straight(feed, 0.0, 0.0, with_xy(end, cx, cy), source);
    current_ = with_xy(end, cx, cy);
    programmed_ = end;
    return;
  }

  const bool left = side_ == Side::Left;
  double theta = std::atan2(cy - opy, cx - opx);  // from the programmed point to the tool
  double alpha = std::atan2(py - opy, px - opx);  // of the new programmed line
  double beta;                                    // turn at the corner, -pi/2 .. 3pi/2
  double gamma;
  if (left) {
    if (theta < alpha) theta = theta + 2 * kPi;
    beta = (theta - alpha) - kHalfPi;
    gamma = kHalfPi;
  } else {
    if (alpha < theta) alpha = alpha + 2 * kPi;
    beta = (alpha - theta) - kHalfPi;
    gamma = -kHalfPi;
  }
  const double end_x = px + radius_ * std::cos(alpha + gamma);
  const double end_y = py + radius_ * std::sin(alpha + gamma);
  double mid_x = opx + radius_ * std::cos(alpha + gamma);
  double mid_y = opy + radius_ * std::sin(alpha + gamma);

  const Queued* front = front_motion();
  const ArcFeed* front_arc = front ? std::get_if<ArcFeed>(&front->call.data) : nullptr;
  bool concave = false;
  if (beta < -kConcaveCorner || beta > kPi + kConcaveCorner) {
    concave = true;
  } else if (beta > kPi - kConcaveCorner && !queue_.empty() && front_arc &&
             ((!left && front_arc->rotation > 0) || (left && front_arc->rotation < 0))) {
    // Leaving an arc that turned away from the tool, almost reversing: LinuxCNC keeps the tool
    // on the near side (the "h" shape) instead of looping around.
    concave = true;
  }

  if (!concave && beta > kConcaveCorner) {  // convex corner: go around it on an arc
    move_endpoint_and_flush(cx, cy, source);
    if (feed) {
      enqueue_arc(0.0, arc_to(mid_x, mid_y, opx, opy, left ? -1 : 1, cz, end), source);
    } else {
      // There is no arc traverse: a straight rapid to the start of the next line.
      Pose corner = end;
      corner.x = mid_x;
      corner.y = mid_y;
      corner.z = cz;
      enqueue_straight(false, 0.0, 0.0, corner, source);
    }
    dequeue();
    set_endpoint(mid_x, mid_y);
  } else if (concave) {
    if (!front_arc) {  // line -> line: pull the previous line's end back along it
      const double halfcorner = (beta + kPi) / 2.0;
      if (halfcorner == 0.0) fail(source, "Zero degree inside corner is invalid for cutter compensation");
      const double retreat = radius_ / std::tan(halfcorner);
      mid_x = cx + retreat * std::cos(theta + gamma);
      mid_y = cy + retreat * std::sin(theta + gamma);
      move_endpoint_and_flush(mid_x, mid_y, source);
    } else {  // arc -> line: where the compensated arc meets the offset line
      const ArcFeed prev = *front_arc;
      const double oldrad = std::hypot(prev.second_axis - prev.second_end, prev.first_axis - prev.first_end);
      const double base_dir = std::atan2(py - opy, px - opx);
      const double normal = prev.rotation > 0 ? base_dir + kHalfPi : base_dir - kHalfPi;
      const double phi = std::atan2(prev.second_axis - opy, prev.first_axis - opx);
      const bool inside = tool_inside_arc(side_, prev.rotation);
      const double oldrad_uncomp = inside ? oldrad + radius_ : oldrad - radius_;
      const double d = oldrad_uncomp * std::cos(normal - phi);  // old centre to the new line
      const double l = (inside ? d - radius_ : d + radius_) / oldrad;
      if (l > 1.0 || l < -1.0)
        fail(source, "Arc to straight motion makes a corner the compensated tool can't fit in without gouging");
      double angle;
      if (inside) angle = prev.rotation > 0 ? -std::acos(l) + normal + kPi : std::acos(l) + normal + kPi;
      else angle = prev.rotation > 0 ? std::acos(l) + normal + kPi : -std::acos(l) + normal + kPi;
      mid_x = prev.first_axis + oldrad * std::cos(angle);
      mid_y = prev.second_axis + oldrad * std::sin(angle);
      move_endpoint_and_flush(mid_x, mid_y, source);
    }
  } else {  // straight on, or tangent
    dequeue();
    set_endpoint(cx, cy);
  }
  enqueue_straight(feed, px - opx, py - opy, with_xy(end, end_x, end_y), source);
  current_ = with_xy(end, end_x, end_y);
  programmed_ = end;
}

// ---- Arcs (LinuxCNC convert_arc_comp1 / comp2)

void CutterCompensation::arc(const ArcFeed& programmed_arc, const Source& source) {
  if (!active() || radius_ <= 0.0) {
    emit(Call{programmed_arc, source, std::nullopt});
    current_ = end_of(programmed_arc);
    programmed_ = current_;
    return;
  }
  if (first_move_) arc_first(programmed_arc, source);
  else arc_next(programmed_arc, source);
}

// Entry arc: through the programmed end offset by the radius, tangent to the tool where it is.
void CutterCompensation::arc_first(const ArcFeed& arc, const Source& source) {
  const double cx = current_.x;
  const double cy = current_.y;
  double end_x = arc.first_end;
  double end_y = arc.second_end;
  double center_x = arc.first_axis;
  double center_y = arc.second_axis;
  const int turn = arc.rotation;
  const bool inside = tool_inside_arc(side_, turn);

  if (std::hypot(end_x - cx, end_y - cy) <= radius_)
    fail(source, "Radius of cutter compensation entry arc is not greater than the tool radius");
  if (inside && std::hypot(center_x - cx, center_y - cy) <= radius_)
    fail(source, "Tool radius not less than arc radius with comp");

  const double gamma = inside ? std::atan2(center_y - end_y, center_x - end_x)
                              : std::atan2(end_y - center_y, end_x - center_x);
  first_move_ = false;
  programmed_ = end_of(arc);

  end_x += radius_ * std::cos(gamma);
  end_y += radius_ * std::sin(gamma);

  // Triangle: A = compensated end, B = new centre, C = midpoint of the compensated chord.
  const double b_len = std::hypot(cy - end_y, cx - end_x) / 2.0;
  const double ab_angle = std::atan2(center_y - end_y, center_x - end_x);
  const double a_angle = std::atan2(cy - end_y, cx - end_x) - ab_angle;
  if (std::fabs(std::cos(a_angle)) < kEqual) fail(source, "Tool radius not less than arc radius with comp");
  const double c_len = b_len / std::cos(a_angle);
  center_x = end_x + c_len * std::cos(ab_angle);
  center_y = end_y + c_len * std::sin(ab_angle);

  const double spiral_tolerance =
      units_ == canonical::Units::Inches ? 2 * 0.001 * M_SQRT2 : 2 * 0.01 * M_SQRT2;
  if (std::fabs(std::hypot(center_x - end_x, center_y - end_y) - std::hypot(center_x - cx, center_y - cy)) >
      spiral_tolerance)
    fail(source, "Bug in tool radius comp");

  const Pose axes = end_of(arc);
  enqueue_arc(sweep(cx, cy, center_x, center_y, turn, end_x, end_y),
              arc_to(end_x, end_y, center_x, center_y, turn, arc.axis_end_point, axes), source);
  current_ = with_xy(axes, end_x, end_y);
}

void CutterCompensation::arc_next(const ArcFeed& arc, const Source& source) {
  const double opx = programmed_.x;
  const double opy = programmed_.y;
  const double cx = current_.x;
  const double cy = current_.y;
  const double cz = current_.z;
  const double end_x = arc.first_end;
  const double end_y = arc.second_end;
  const double centerx = arc.first_axis;
  const double centery = arc.second_axis;
  const int turn = arc.rotation;
  const bool left = side_ == Side::Left;
  const bool counterclockwise = turn > 0;

  const double arc_radius = std::hypot(centerx - end_x, centery - end_y);
  double theta = std::atan2(cy - opy, cx - opx);     // tangent of the last cut
  theta = left ? theta - kHalfPi : theta + kHalfPi;
  double delta = std::atan2(centery - opy, centerx - opx);  // start of the arc to its centre
  const double alpha = counterclockwise ? delta - kHalfPi : delta + kHalfPi;  // arc tangent
  double beta = left ? theta - alpha : alpha - theta;
  beta = beta > 1.5 * kPi ? beta - 2 * kPi : beta < -kHalfPi ? beta + 2 * kPi : beta;

  double gamma;
  const bool inside = tool_inside_arc(side_, turn);
  if (inside) {
    gamma = std::atan2(centery - end_y, centerx - end_x);
    if (arc_radius <= radius_) fail(source, "Tool radius not less than arc radius with comp");
  } else {
    gamma = std::atan2(end_y - centery, end_x - centerx);
    delta = delta + kPi;
  }
  const double new_end_x = end_x + radius_ * std::cos(gamma);
  const double new_end_y = end_y + radius_ * std::sin(gamma);
  const Pose axes = end_of(arc);
  const ArcFeed compensated = arc_to(new_end_x, new_end_y, centerx, centery, turn, arc.axis_end_point, axes);
  const double programmed_sweep = sweep(opx, opy, centerx, centery, turn, end_x, end_y);

  if (beta < -kConcaveCorner || beta > kPi + kConcaveCorner ||
      // tangent arc after arc or line where the tool must stay outside ("m" and "h" shapes)
      (std::fabs(beta - kPi) < kConcaveCorner && !inside)) {
    const Queued* front = front_motion();
    const ArcFeed* prev = front ? std::get_if<ArcFeed>(&front->call.data) : nullptr;
    double mid_x;
    double mid_y;
    if (!prev) {  // line -> arc
      const double offset = arc_radius * std::sin(beta - kHalfPi);
      double angle;
      if (inside) {
        const double dist = arc_radius - radius_;
        const double l = (offset + radius_) / dist;
        if (l > 1.0 || l < -1.0) fail(source, "Arc move in concave corner cannot be reached by the tool without gouging");
        angle = turn > 0 ? theta + std::asin(l) : theta - std::asin(l);
        mid_x = centerx + dist * std::cos(angle);
        mid_y = centery + dist * std::sin(angle);
      } else {
        const double dist = arc_radius + radius_;
        const double l = (offset - radius_) / dist;
        if (l > 1.0 || l < -1.0) fail(source, "Arc move in concave corner cannot be reached by the tool without gouging");
        angle = turn > 0 ? theta + kPi - std::asin(l) : theta + kPi + std::asin(l);
        mid_x = centerx + dist * std::cos(angle);
        mid_y = centery + dist * std::sin(angle);
      }
    } else {  // arc -> arc: intersect the two compensated circles
      const double oldrad = std::hypot(prev->second_axis - prev->second_end, prev->first_axis - prev->first_end);
      const double newrad = inside ? arc_radius - radius_ : arc_radius + radius_;
      const double arc_cc = std::hypot(prev->second_axis - centery, prev->first_axis - centerx);
      if (oldrad == 0 || arc_cc == 0)
        fail(source, "Arc to arc motion is invalid because the arcs have the same center");
      const double a = (oldrad * oldrad + arc_cc * arc_cc - newrad * newrad) / (2 * oldrad * arc_cc);
      if (a > 1.0 || a < -1.0)
        fail(source, "Arc to arc motion makes a corner the compensated tool can't fit in without gouging");
      const double pullback = std::acos(a);
      const double cc_dir = std::atan2(centery - prev->second_axis, centerx - prev->first_axis);
      double dir;
      if (tool_inside_arc(side_, prev->rotation)) dir = turn > 0 ? cc_dir + pullback : cc_dir - pullback;
      else dir = turn > 0 ? cc_dir - pullback : cc_dir + pullback;
      mid_x = prev->first_axis + oldrad * std::cos(dir);
      mid_y = prev->second_axis + oldrad * std::sin(dir);
    }
    move_endpoint_and_flush(mid_x, mid_y, source);
    enqueue_arc(programmed_sweep, compensated, source);
  } else if (beta > kConcaveCorner) {  // convex: a corner arc, then the arc
    const double mid_x = opx + radius_ * std::cos(delta);
    const double mid_y = opy + radius_ * std::sin(delta);
    dequeue();
    enqueue_arc(0.0, arc_to(mid_x, mid_y, opx, opy, left ? -1 : 1, cz, axes), source);
    dequeue();
    set_endpoint(mid_x, mid_y);
    enqueue_arc(programmed_sweep, compensated, source);
  } else {  // tangent
    dequeue();
    set_endpoint(cx, cy);
    enqueue_arc(programmed_sweep, compensated, source);
  }
  programmed_ = axes;
  current_ = with_xy(axes, new_end_x, new_end_y);
}

// ---- The queue (LinuxCNC interp_queue.cc)

void CutterCompensation::enqueue_straight(bool feed, double dx, double dy, const Pose& end,
                                          const Source& source) {
  Queued q;
  if (feed) q.call = Call{canonical::StraightFeed{end}, source, std::nullopt};
  else q.call = Call{canonical::StraightTraverse{end}, source, std::nullopt};
  q.dx = dx;
  q.dy = dy;
  queue_.push_back(std::move(q));
}

void CutterCompensation::enqueue_arc(double original_turns, const ArcFeed& arc, const Source& source) {
  Queued q;
  q.call = Call{arc, source, std::nullopt};
  q.original_turns = original_turns;
  queue_.push_back(std::move(q));
}

// Moves the end of every queued move to (x, y) (the corner point found for the next move),
// refusing when that would reverse a line or lengthen an arc (the tool would gouge), then
// emits the queue.
void CutterCompensation::move_endpoint_and_flush(double x, double y, const Source& source) {
  if (queue_.empty()) return;
  for (Queued& q : queue_) {
    if (auto* arc = std::get_if<ArcFeed>(&q.call.data)) {
      const double r1 = std::hypot(arc->first_end - arc->first_axis, arc->second_end - arc->second_axis);
      arc->first_end = x;
      arc->second_end = y;
      const double r2 = std::hypot(x - arc->first_axis, y - arc->second_axis);
      const double new_sweep = sweep(endpoint_x_, endpoint_y_, arc->first_axis, arc->second_axis,
                                     arc->rotation, x, y);
      if (std::fabs(r1 - r2) > kMismatchedRadii) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "BUG: cutter compensation has generated an invalid arc with mismatched radii r1 %f r2 %f",
                      r1, r2);
        fail(source, text);
      }
      if (q.original_turns != 0 && endpoint_valid_ &&
          std::fabs(new_sweep) > std::fabs(q.original_turns) + kSweepSlack)
        fail(source, "Arc move in concave corner cannot be reached by the tool without gouging");
      continue;
    }
    Pose* end = nullptr;
    const char* message = nullptr;
    if (auto* feed = std::get_if<canonical::StraightFeed>(&q.call.data)) {
      end = &feed->end;
      message = "Straight feed in concave corner cannot be reached by the tool without gouging";
    } else if (auto* traverse = std::get_if<canonical::StraightTraverse>(&q.call.data)) {
      end = &traverse->end;
      message = "Straight traverse in concave corner cannot be reached by the tool without gouging";
    } else {
      continue;
    }
    const double dot = q.dx * (x - endpoint_x_) + q.dy * (y - endpoint_y_);
    if (endpoint_valid_ && dot < 0) fail(source, message);
    end->x = x;
    end->y = y;
  }
  dequeue();
  set_endpoint(x, y);
}

void CutterCompensation::dequeue() {
  endpoint_valid_ = false;
  if (queue_.empty()) return;
  last_front_ = queue_.front();
  for (const Queued& q : queue_) emit(q.call);
  queue_.clear();
}

void CutterCompensation::set_endpoint(double x, double y) {
  endpoint_x_ = x;
  endpoint_y_ = y;
  endpoint_valid_ = true;
}

// The oldest pending move. LinuxCNC reads the front of its queue even when it is empty, and
// then sees the first move of the queue it emitted last; so do we.
const CutterCompensation::Queued* CutterCompensation::front_motion() const {
  if (!queue_.empty()) return &queue_.front();
  return last_front_ ? &*last_front_ : nullptr;
}

void CutterCompensation::scale(double factor) {
  for (Queued& q : queue_) {
    endpoint_x_ *= factor;  // once per queued call, as LinuxCNC's qc_scale does
    endpoint_y_ *= factor;
    if (auto* arc = std::get_if<ArcFeed>(&q.call.data)) {
      arc->first_end *= factor;
      arc->second_end *= factor;
      arc->axis_end_point *= factor;
      arc->first_axis *= factor;
      arc->second_axis *= factor;
      arc->u *= factor;
      arc->v *= factor;
      arc->w *= factor;
    } else if (auto* feed = std::get_if<canonical::StraightFeed>(&q.call.data)) {
      scale_pose(feed->end, factor);
    } else if (auto* traverse = std::get_if<canonical::StraightTraverse>(&q.call.data)) {
      scale_pose(traverse->end, factor);
    }
  }
  scale_pose(current_, factor);
  scale_pose(programmed_, factor);
  radius_ *= factor;
}

void CutterCompensation::emit(const Call& call) { out_.call(call); }

void CutterCompensation::fail(const Source& source, std::string message) const {
  SourceLocation where = locate_ ? locate_(source) : SourceLocation{{}, source.line, 0};
  throw InputError(std::move(where), std::move(message));
}

}  // namespace ncbridge::interpreter
