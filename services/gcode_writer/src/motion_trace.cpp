#include "motion_trace.hpp"

#include <cmath>
#include <type_traits>
#include <vector>

namespace ncbridge::gcode_writer {

using namespace canonical;

namespace {

struct Step {
  const Data* call;
  MachineState state;
};

bool is_state_call(const Data& d) {
  return std::holds_alternative<UseLengthUnits>(d) || std::holds_alternative<SetG5xOffset>(d) ||
         std::holds_alternative<SetG92Offset>(d) || std::holds_alternative<SetXyRotation>(d) ||
         std::holds_alternative<SelectPlane>(d) || std::holds_alternative<SetTraverseRate>(d) ||
         std::holds_alternative<SetFeedRate>(d) || std::holds_alternative<SetFeedReference>(d) ||
         std::holds_alternative<SetFeedMode>(d) || std::holds_alternative<SetMotionControlMode>(d) ||
         std::holds_alternative<SetNaivecamTolerance>(d) || std::holds_alternative<SetSpindleSpeed>(d) ||
         std::holds_alternative<StartSpindleClockwise>(d) || std::holds_alternative<StartSpindleCounterclockwise>(d) ||
         std::holds_alternative<StopSpindleTurning>(d) || std::holds_alternative<SetSpindleMode>(d) ||
         std::holds_alternative<UseToolLengthOffset>(d) || std::holds_alternative<SelectTool>(d) ||
         std::holds_alternative<FloodOn>(d) || std::holds_alternative<FloodOff>(d) || std::holds_alternative<MistOn>(d) ||
         std::holds_alternative<MistOff>(d) || std::holds_alternative<EnableFeedOverride>(d) ||
         std::holds_alternative<DisableFeedOverride>(d) || std::holds_alternative<EnableSpeedOverride>(d) ||
         std::holds_alternative<DisableSpeedOverride>(d) || std::holds_alternative<EnableAdaptiveFeed>(d) ||
         std::holds_alternative<DisableAdaptiveFeed>(d) || std::holds_alternative<EnableFeedHold>(d) ||
         std::holds_alternative<DisableFeedHold>(d) || std::holds_alternative<StartChange>(d);
}

std::vector<Step> steps_of(MachineState s, std::span<const Data> calls) {
  std::vector<Step> steps;
  for (const Data& d : calls) {
    if (std::holds_alternative<Comment>(d) || std::holds_alternative<Message>(d) || std::holds_alternative<OnReset>(d) ||
        std::holds_alternative<Finish>(d)) {
      continue;
    }
    if (is_state_call(d)) {
      s.apply(d);
      continue;
    }
    if (const auto* t = std::get_if<StraightTraverse>(&d); t && near(t->end, s.position)) {
      continue;
    }
    if (const auto* f = std::get_if<StraightFeed>(&d); f && near(f->end, s.position)) {
      continue;
    }
    steps.push_back({&d, s});
    s.apply(d);
  }
  return steps;
}

bool same_actuators(const MachineState& a, const MachineState& b, double tol) {
  return a.spindle == b.spindle && near(a.speed, b.speed, tol) && near(a.css_maximum, b.css_maximum, tol) &&
         a.flood == b.flood && a.mist == b.mist;
}

bool same_path(const MachineState& a, const MachineState& b, double tol) {
  if (a.control != b.control) return false;
  if (a.control != MotionControlMode::Continuous) return true;
  return near(a.tolerance, b.tolerance, tol) && near(a.naive_tolerance, b.naive_tolerance, tol);
}

bool same_frame(const MachineState& a, const MachineState& b, double tol) {
  return a.units == b.units && near(a.origin_mm(), b.origin_mm(), tol) &&
         near(a.active_rotation(), b.active_rotation(), tol) && near(a.tool_offset_mm, b.tool_offset_mm, tol);
}

bool same_feed(const MachineState& a, const MachineState& b, double tol) {
  return a.feed_mode == b.feed_mode && near(a.feed_mm, b.feed_mm, tol * a.mm_per_unit()) && a.feed_override == b.feed_override &&
         a.speed_override == b.speed_override && a.adaptive_feed == b.adaptive_feed && a.feed_hold == b.feed_hold;
}

bool same_step(const Step& a, const Step& b, double tol) {
  if (a.call->index() != b.call->index()) return false;
  const Data& x = *a.call;
  const Data& y = *b.call;
  if (const auto* t = std::get_if<StraightTraverse>(&x)) {
    // a rapid is positioning: how the control blends it into the next move is its own business
    return near(t->end, std::get<StraightTraverse>(y).end, tol) && same_frame(a.state, b.state, tol) &&
           same_actuators(a.state, b.state, tol);
  }
  if (const auto* f = std::get_if<StraightFeed>(&x)) {
    return near(f->end, std::get<StraightFeed>(y).end, tol) && same_frame(a.state, b.state, tol) &&
           same_actuators(a.state, b.state, tol) && same_path(a.state, b.state, tol) && same_feed(a.state, b.state, tol);
  }
  if (const auto* r = std::get_if<ArcFeed>(&x)) {
    const auto& q = std::get<ArcFeed>(y);
    return a.state.plane == b.state.plane && near(r->first_end, q.first_end, tol) && near(r->second_end, q.second_end, tol) &&
           near(r->first_axis, q.first_axis, tol) && near(r->second_axis, q.second_axis, tol) && r->rotation == q.rotation &&
           near(r->axis_end_point, q.axis_end_point, tol) && same_frame(a.state, b.state, tol) &&
           same_actuators(a.state, b.state, tol) && same_path(a.state, b.state, tol) && same_feed(a.state, b.state, tol);
  }
  if (const auto* w = std::get_if<Dwell>(&x)) {
    return near(w->seconds, std::get<Dwell>(y).seconds, tol) && same_actuators(a.state, b.state, tol);
  }
  if (const auto* o = std::get_if<OrientSpindle>(&x)) {
    const auto& p = std::get<OrientSpindle>(y);
    return near(o->orientation, p.orientation, tol) && o->mode == p.mode;
  }
  if (const auto* r = std::get_if<RigidTap>(&x)) {
    return near(r->end, std::get<RigidTap>(y).end, tol) && same_frame(a.state, b.state, tol);
  }
  // stops and the other actions: the call itself
  return true;
}

}  // namespace

bool same_motion(const MachineState& start_a, std::span<const Data> a, const MachineState& start_b,
                 std::span<const Data> b, double tolerance) {
  const std::vector<Step> sa = steps_of(start_a, a);
  const std::vector<Step> sb = steps_of(start_b, b);
  if (sa.size() != sb.size()) return false;
  for (std::size_t i = 0; i < sa.size(); ++i) {
    if (!same_step(sa[i], sb[i], tolerance)) return false;
  }
  return true;
}

}  // namespace ncbridge::gcode_writer
