// ncbridge::canonical::Call <-> proto/canonical.proto, one alternative at a time.
#include "ncbridge/canonical/proto_codec.hpp"

#include <google/protobuf/arena.h>

#include <limits>
#include <type_traits>

#include "canonical.pb.h"
#include "ncbridge/common/error.hpp"

namespace ncbridge::canonical {
namespace {

namespace w = ncbridge::pb;

// Every alternative of Data has a case below; a new alternative must be added here too.
static_assert(std::variant_size_v<Data> == 64, "canonical::Data changed: update canonical.proto and this codec");

[[noreturn]] void malformed(const std::string& what) {
  throw InputError({"<canonical batch>", 0, 0}, what);
}

// ---- encoding

void put_pose(const Pose& p, w::Pose& out) {
  out.set_x(p.x); out.set_y(p.y); out.set_z(p.z);
  out.set_a(p.a); out.set_b(p.b); out.set_c(p.c);
  out.set_u(p.u); out.set_v(p.v); out.set_w(p.w);
}

struct DataEncoder {
  w::Call& out;

  void operator()(const UseLengthUnits& d) { out.mutable_use_length_units()->set_units(static_cast<w::Units>(d.units)); }
  void operator()(const SetG5xOffset& d) {
    auto* m = out.mutable_set_g5x_offset();
    m->set_index(d.index);
    put_pose(d.offset, *m->mutable_offset());
  }
  void operator()(const SetG92Offset& d) { put_pose(d.offset, *out.mutable_set_g92_offset()->mutable_offset()); }
  void operator()(const SetXyRotation& d) { out.mutable_set_xy_rotation()->set_degrees(d.degrees); }
  void operator()(const SelectPlane& d) { out.mutable_select_plane()->set_plane(static_cast<w::Plane>(d.plane)); }
  void operator()(const SetTraverseRate& d) { out.mutable_set_traverse_rate()->set_rate(d.rate); }
  void operator()(const StraightTraverse& d) { put_pose(d.end, *out.mutable_straight_traverse()->mutable_end()); }
  void operator()(const SetFeedRate& d) { out.mutable_set_feed_rate()->set_rate(d.rate); }
  void operator()(const SetFeedReference& d) {
    out.mutable_set_feed_reference()->set_reference(static_cast<w::FeedReference>(d.reference));
  }
  void operator()(const SetFeedMode& d) {
    auto* m = out.mutable_set_feed_mode();
    m->set_spindle(d.spindle);
    m->set_mode(d.mode);
  }
  void operator()(const SetMotionControlMode& d) {
    auto* m = out.mutable_set_motion_control_mode();
    m->set_mode(static_cast<w::MotionControlMode>(d.mode));
    m->set_tolerance(d.tolerance);
  }
  void operator()(const SetNaivecamTolerance& d) { out.mutable_set_naivecam_tolerance()->set_tolerance(d.tolerance); }
  void operator()(const SetCutterRadiusCompensation& d) { out.mutable_set_cutter_radius_compensation()->set_radius(d.radius); }
  void operator()(const StartCutterRadiusCompensation& d) {
    out.mutable_start_cutter_radius_compensation()->set_side(static_cast<w::Side>(d.side));
  }
  void operator()(const StopCutterRadiusCompensation&) { out.mutable_stop_cutter_radius_compensation(); }
  void operator()(const StartSpeedFeedSynch& d) {
    auto* m = out.mutable_start_speed_feed_synch();
    m->set_spindle(d.spindle);
    m->set_feed_per_revolution(d.feed_per_revolution);
    m->set_velocity_mode(d.velocity_mode);
  }
  void operator()(const StopSpeedFeedSynch&) { out.mutable_stop_speed_feed_synch(); }
  void operator()(const ArcFeed& d) {
    auto* m = out.mutable_arc_feed();
    m->set_first_end(d.first_end); m->set_second_end(d.second_end);
    m->set_first_axis(d.first_axis); m->set_second_axis(d.second_axis);
    m->set_rotation(d.rotation);
    m->set_axis_end_point(d.axis_end_point);
    m->set_a(d.a); m->set_b(d.b); m->set_c(d.c); m->set_u(d.u); m->set_v(d.v); m->set_w(d.w);
  }
  void operator()(const StraightFeed& d) { put_pose(d.end, *out.mutable_straight_feed()->mutable_end()); }
  void operator()(const StraightProbe& d) {
    put_pose(d.end, *out.mutable_straight_probe()->mutable_end());
    out.mutable_straight_probe()->set_probe_type(d.probe_type);
  }
  void operator()(const RigidTap& d) {
    auto* m = out.mutable_rigid_tap();
    put_pose(d.end, *m->mutable_end());
    m->set_scale(d.scale);
  }
  void operator()(const Dwell& d) { out.mutable_dwell()->set_seconds(d.seconds); }
  void operator()(const SetSpindleSpeed& d) {
    auto* m = out.mutable_set_spindle_speed();
    m->set_spindle(d.spindle);
    m->set_rpm(d.rpm);
  }
  void operator()(const StartSpindleClockwise& d) { out.mutable_start_spindle_clockwise()->set_spindle(d.spindle); }
  void operator()(const StartSpindleCounterclockwise& d) { out.mutable_start_spindle_counterclockwise()->set_spindle(d.spindle); }
  void operator()(const StopSpindleTurning& d) { out.mutable_stop_spindle_turning()->set_spindle(d.spindle); }
  void operator()(const SetSpindleMode& d) {
    auto* m = out.mutable_set_spindle_mode();
    m->set_spindle(d.spindle);
    m->set_css_maximum(d.css_maximum);
  }
  void operator()(const OrientSpindle& d) {
    auto* m = out.mutable_orient_spindle();
    m->set_spindle(d.spindle);
    m->set_orientation(d.orientation);
    m->set_mode(d.mode);
  }
  void operator()(const SpindleRetract&) { out.mutable_spindle_retract(); }
  void operator()(const UseToolLengthOffset& d) { put_pose(d.offset, *out.mutable_use_tool_length_offset()->mutable_offset()); }
  void operator()(const SelectTool& d) { out.mutable_select_tool()->set_tool(d.tool); }
  void operator()(const StartChange&) { out.mutable_start_change(); }
  void operator()(const ChangeTool& d) { out.mutable_change_tool()->set_slot(d.slot); }
  void operator()(const ChangeToolNumber& d) {
    out.mutable_change_tool_number()->set_number(d.number);
    out.mutable_change_tool_number()->set_pocket(d.pocket);
  }
  void operator()(const Comment& d) { out.mutable_comment()->set_text(d.text); }
  void operator()(const Message& d) { out.mutable_message()->set_text(d.text); }
  void operator()(const FloodOn&) { out.mutable_flood_on(); }
  void operator()(const FloodOff&) { out.mutable_flood_off(); }
  void operator()(const MistOn&) { out.mutable_mist_on(); }
  void operator()(const MistOff&) { out.mutable_mist_off(); }
  void operator()(const EnableFeedOverride& d) { out.mutable_enable_feed_override()->set_spindle(d.spindle); }
  void operator()(const DisableFeedOverride& d) { out.mutable_disable_feed_override()->set_spindle(d.spindle); }
  void operator()(const EnableSpeedOverride& d) { out.mutable_enable_speed_override()->set_spindle(d.spindle); }
  void operator()(const DisableSpeedOverride& d) { out.mutable_disable_speed_override()->set_spindle(d.spindle); }
  void operator()(const EnableAdaptiveFeed&) { out.mutable_enable_adaptive_feed(); }
  void operator()(const DisableAdaptiveFeed&) { out.mutable_disable_adaptive_feed(); }
  void operator()(const EnableFeedHold&) { out.mutable_enable_feed_hold(); }
  void operator()(const DisableFeedHold&) { out.mutable_disable_feed_hold(); }
  void operator()(const OptionalProgramStop&) { out.mutable_optional_program_stop(); }
  void operator()(const ProgramStop&) { out.mutable_program_stop(); }
  void operator()(const ProgramEnd&) { out.mutable_program_end(); }
  void operator()(const PalletShuttle&) { out.mutable_pallet_shuttle(); }
  void operator()(const OnReset&) { out.mutable_on_reset(); }
  void operator()(const WaitSpindleOrientComplete& d) {
    auto* m = out.mutable_wait_spindle_orient_complete();
    m->set_spindle(d.spindle);
    m->set_timeout(d.timeout);
  }
  void operator()(const Finish&) { out.mutable_finish(); }
  void operator()(const SetToolTableEntry& d) {
    auto* m = out.mutable_set_tool_table_entry();
    m->set_pocket(d.pocket);
    m->set_tool(d.tool);
    put_pose(d.offset, *m->mutable_offset());
    m->set_diameter(d.diameter);
    m->set_frontangle(d.frontangle);
    m->set_backangle(d.backangle);
    m->set_orientation(d.orientation);
  }
  void operator()(const NurbsFeed& d) {
    auto* m = out.mutable_nurbs_feed();
    m->mutable_control_points()->Reserve(static_cast<int>(d.control_points.size()));
    for (const NurbsControlPoint& p : d.control_points) {
      auto* q = m->add_control_points();
      q->set_x(p.x);
      q->set_y(p.y);
      q->set_weight(p.weight);
    }
    m->set_order(d.order);
  }
  void operator()(const TurnProbeOn&) { out.mutable_turn_probe_on(); }
  void operator()(const TurnProbeOff&) { out.mutable_turn_probe_off(); }
  void operator()(const LogOpen& d) { out.mutable_log_open()->set_text(d.path); }
  void operator()(const LogAppend& d) { out.mutable_log_append()->set_text(d.path); }
  void operator()(const LogClose&) { out.mutable_log_close(); }
  void operator()(const Log& d) { out.mutable_log()->set_text(d.text); }
  void operator()(const Print& d) { out.mutable_print()->set_text(d.text); }
};

void put_call(const Call& call, w::Call& out) {
  auto* src = out.mutable_source();
  src->set_file(call.source.file);
  src->set_line(call.source.line);
  if (call.source.n_number != -1) src->set_n_number(call.source.n_number);
  src->set_n_digits(call.source.n_digits);
  if (call.cycle) {
    const CycleTag& c = *call.cycle;
    auto* m = out.mutable_cycle();
    m->set_cycle_id(c.cycle_id);
    m->set_g_code_x10(c.g_code_x10);
    m->set_retract_to_r(c.retract_to_r);
    m->set_plane(c.plane);
    m->set_x(c.x); m->set_y(c.y);
    m->set_clearance(c.clearance); m->set_r(c.r); m->set_z(c.z);
    m->set_q(c.q); m->set_p(c.p); m->set_k(c.k);
    m->set_repeat(c.repeat);
  }
  std::visit(DataEncoder{out}, call.data);
}

// ---- decoding

struct CallContext {
  std::uint64_t seq;
  std::size_t index;
};

[[noreturn]] void bad_call(const CallContext& at, const std::string& what) {
  malformed("batch " + std::to_string(at.seq) + ", call " + std::to_string(at.index) + ": " + what);
}

template <class E>
E enum_value(int v, int count, const CallContext& at, const char* what) {
  if (v < 0 || v >= count) bad_call(at, std::string(what) + " out of range: " + std::to_string(v));
  return static_cast<E>(v);
}

Pose get_pose(const w::Pose& p) { return {p.x(), p.y(), p.z(), p.a(), p.b(), p.c(), p.u(), p.v(), p.w()}; }

Data get_data(const w::Call& in, const CallContext& at) {
  using C = w::Call;
  switch (in.data_case()) {
    case C::kUseLengthUnits:
      return UseLengthUnits{enum_value<Units>(in.use_length_units().units(), 2, at, "units")};
    case C::kSetG5XOffset:
      return SetG5xOffset{in.set_g5x_offset().index(), get_pose(in.set_g5x_offset().offset())};
    case C::kSetG92Offset: return SetG92Offset{get_pose(in.set_g92_offset().offset())};
    case C::kSetXyRotation: return SetXyRotation{in.set_xy_rotation().degrees()};
    case C::kSelectPlane: return SelectPlane{enum_value<Plane>(in.select_plane().plane(), 6, at, "plane")};
    case C::kSetTraverseRate: return SetTraverseRate{in.set_traverse_rate().rate()};
    case C::kStraightTraverse: return StraightTraverse{get_pose(in.straight_traverse().end())};
    case C::kSetFeedRate: return SetFeedRate{in.set_feed_rate().rate()};
    case C::kSetFeedReference:
      return SetFeedReference{enum_value<FeedReference>(in.set_feed_reference().reference(), 2, at, "feed reference")};
    case C::kSetFeedMode: return SetFeedMode{in.set_feed_mode().spindle(), in.set_feed_mode().mode()};
    case C::kSetMotionControlMode: {
      const auto& m = in.set_motion_control_mode();
      return SetMotionControlMode{enum_value<MotionControlMode>(m.mode(), 3, at, "motion control mode"), m.tolerance()};
    }
    case C::kSetNaivecamTolerance: return SetNaivecamTolerance{in.set_naivecam_tolerance().tolerance()};
    case C::kSetCutterRadiusCompensation:
      return SetCutterRadiusCompensation{in.set_cutter_radius_compensation().radius()};
    case C::kStartCutterRadiusCompensation:
      return StartCutterRadiusCompensation{enum_value<Side>(in.start_cutter_radius_compensation().side(), 3, at, "side")};
    case C::kStopCutterRadiusCompensation: return StopCutterRadiusCompensation{};
    case C::kStartSpeedFeedSynch: {
      const auto& m = in.start_speed_feed_synch();
      return StartSpeedFeedSynch{m.spindle(), m.feed_per_revolution(), m.velocity_mode()};
    }
    case C::kStopSpeedFeedSynch: return StopSpeedFeedSynch{};
    case C::kArcFeed: {
      const auto& m = in.arc_feed();
      return ArcFeed{m.first_end(), m.second_end(), m.first_axis(), m.second_axis(), m.rotation(),
                     m.axis_end_point(), m.a(), m.b(), m.c(), m.u(), m.v(), m.w()};
    }
    case C::kStraightFeed: return StraightFeed{get_pose(in.straight_feed().end())};
    case C::kStraightProbe: {
      if (in.straight_probe().probe_type() > std::numeric_limits<std::uint8_t>::max()) bad_call(at, "probe_type out of range");
      return StraightProbe{get_pose(in.straight_probe().end()), static_cast<std::uint8_t>(in.straight_probe().probe_type())};
    }
    case C::kRigidTap: return RigidTap{get_pose(in.rigid_tap().end()), in.rigid_tap().scale()};
    case C::kDwell: return Dwell{in.dwell().seconds()};
    case C::kSetSpindleSpeed: return SetSpindleSpeed{in.set_spindle_speed().spindle(), in.set_spindle_speed().rpm()};
    case C::kStartSpindleClockwise: return StartSpindleClockwise{in.start_spindle_clockwise().spindle()};
    case C::kStartSpindleCounterclockwise:
      return StartSpindleCounterclockwise{in.start_spindle_counterclockwise().spindle()};
    case C::kStopSpindleTurning: return StopSpindleTurning{in.stop_spindle_turning().spindle()};
    case C::kSetSpindleMode: return SetSpindleMode{in.set_spindle_mode().spindle(), in.set_spindle_mode().css_maximum()};
    case C::kOrientSpindle: {
      const auto& m = in.orient_spindle();
      return OrientSpindle{m.spindle(), m.orientation(), m.mode()};
    }
    case C::kSpindleRetract: return SpindleRetract{};
    case C::kUseToolLengthOffset: return UseToolLengthOffset{get_pose(in.use_tool_length_offset().offset())};
    case C::kSelectTool: return SelectTool{in.select_tool().tool()};
    case C::kStartChange: return StartChange{};
    case C::kChangeTool: return ChangeTool{in.change_tool().slot()};
    case C::kChangeToolNumber:
      return ChangeToolNumber{in.change_tool_number().number(), in.change_tool_number().pocket()};
    case C::kComment: return Comment{in.comment().text()};
    case C::kMessage: return Message{in.message().text()};
    case C::kFloodOn: return FloodOn{};
    case C::kFloodOff: return FloodOff{};
    case C::kMistOn: return MistOn{};
    case C::kMistOff: return MistOff{};
    case C::kEnableFeedOverride: return EnableFeedOverride{in.enable_feed_override().spindle()};
    case C::kDisableFeedOverride: return DisableFeedOverride{in.disable_feed_override().spindle()};
    case C::kEnableSpeedOverride: return EnableSpeedOverride{in.enable_speed_override().spindle()};
    case C::kDisableSpeedOverride: return DisableSpeedOverride{in.disable_speed_override().spindle()};
    case C::kEnableAdaptiveFeed: return EnableAdaptiveFeed{};
    case C::kDisableAdaptiveFeed: return DisableAdaptiveFeed{};
    case C::kEnableFeedHold: return EnableFeedHold{};
    case C::kDisableFeedHold: return DisableFeedHold{};
    case C::kOptionalProgramStop: return OptionalProgramStop{};
    case C::kProgramStop: return ProgramStop{};
    case C::kProgramEnd: return ProgramEnd{};
    case C::kPalletShuttle: return PalletShuttle{};
    case C::kOnReset: return OnReset{};
    case C::kWaitSpindleOrientComplete: {
      const auto& m = in.wait_spindle_orient_complete();
      return WaitSpindleOrientComplete{m.spindle(), m.timeout()};
    }
    case C::kFinish: return Finish{};
    case C::kSetToolTableEntry: {
      const auto& m = in.set_tool_table_entry();
      return SetToolTableEntry{m.pocket(), m.tool(), get_pose(m.offset()), m.diameter(),
                               m.frontangle(), m.backangle(), m.orientation()};
    }
    case C::kNurbsFeed: {
      const auto& m = in.nurbs_feed();
      NurbsFeed f;  // any values: what reads it checks the order against the points
      f.order = m.order();
      f.control_points.reserve(static_cast<std::size_t>(m.control_points_size()));
      for (const auto& p : m.control_points()) f.control_points.push_back({p.x(), p.y(), p.weight()});
      return f;
    }
    case C::kTurnProbeOn: return TurnProbeOn{};
    case C::kTurnProbeOff: return TurnProbeOff{};
    case C::kLogOpen: return LogOpen{in.log_open().text()};
    case C::kLogAppend: return LogAppend{in.log_append().text()};
    case C::kLogClose: return LogClose{};
    case C::kLog: return Log{in.log().text()};
    case C::kPrint: return Print{in.print().text()};
    case C::DATA_NOT_SET: break;
  }
  bad_call(at, "no canonical function (unknown or missing call data)");
}

Call get_call(const w::Call& in, const CallContext& at) {
  Call call{get_data(in, at), {}, std::nullopt};
  const auto& src = in.source();
  call.source.file = src.file();
  call.source.line = src.line();
  call.source.n_number = src.has_n_number() ? src.n_number() : -1;
  if (src.n_digits() > std::numeric_limits<std::uint8_t>::max()) bad_call(at, "n_digits out of range");
  call.source.n_digits = static_cast<std::uint8_t>(src.n_digits());
  if (in.has_cycle()) {
    const auto& m = in.cycle();
    if (m.g_code_x10() > std::numeric_limits<std::uint16_t>::max()) bad_call(at, "cycle g_code_x10 out of range");
    if (m.plane() > std::numeric_limits<std::uint8_t>::max()) bad_call(at, "cycle plane out of range");
    CycleTag c;
    c.cycle_id = m.cycle_id();
    c.g_code_x10 = static_cast<std::uint16_t>(m.g_code_x10());
    c.retract_to_r = m.retract_to_r();
    c.plane = static_cast<std::uint8_t>(m.plane());
    c.x = m.x(); c.y = m.y();
    c.clearance = m.clearance(); c.r = m.r(); c.z = m.z();
    c.q = m.q(); c.p = m.p(); c.k = m.k();
    c.repeat = m.repeat();
    call.cycle = c;
  }
  return call;
}

}  // namespace

std::string encode_batch(const CanonicalBatchView& batch) {
  google::protobuf::Arena arena;
  auto* msg = google::protobuf::Arena::CreateMessage<w::CanonicalBatch>(&arena);
  msg->set_job_id(std::string(batch.job_id));
  msg->set_seq(batch.seq);
  msg->set_last(batch.last);
  for (const SourceFile& f : batch.files) {
    auto* m = msg->add_files();
    m->set_index(f.index);
    m->set_path(f.path);
  }
  msg->mutable_calls()->Reserve(static_cast<int>(batch.calls.size()));
  for (const Call& c : batch.calls) put_call(c, *msg->add_calls());
  msg->set_call_count(batch.calls.size());
  std::string out;
  if (!msg->SerializeToString(&out)) malformed("cannot serialize batch (larger than 2 GiB?)");
  return out;
}

DecodedBatch decode_batch(std::string_view bytes) {
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) malformed("batch larger than 2 GiB");
  google::protobuf::Arena arena;
  auto* msg = google::protobuf::Arena::CreateMessage<w::CanonicalBatch>(&arena);
  if (!msg->ParseFromArray(bytes.data(), static_cast<int>(bytes.size())))
    malformed("not a canonical batch (truncated or malformed Protobuf, " + std::to_string(bytes.size()) + " bytes)");
  if (!msg->has_call_count()) malformed("truncated canonical batch (no call count at its end)");
  if (msg->call_count() != static_cast<std::uint64_t>(msg->calls_size()))
    malformed("truncated canonical batch (" + std::to_string(msg->calls_size()) + " calls of " +
              std::to_string(msg->call_count()) + ")");
  DecodedBatch out;
  out.job_id = msg->job_id();
  out.seq = msg->seq();
  out.last = msg->last();
  out.files.reserve(static_cast<std::size_t>(msg->files_size()));
  for (const auto& f : msg->files()) out.files.push_back({f.index(), f.path()});
  out.calls.reserve(static_cast<std::size_t>(msg->calls_size()));
  for (int i = 0; i < msg->calls_size(); ++i)
    out.calls.push_back(get_call(msg->calls(i), {out.seq, static_cast<std::size_t>(i)}));
  return out;
}

void replay(const DecodedBatch& batch, Sink& sink) {
  for (const SourceFile& f : batch.files) sink.source_file(f.index, f.path);
  for (const Call& c : batch.calls) sink.call(c);
}

}  // namespace ncbridge::canonical
