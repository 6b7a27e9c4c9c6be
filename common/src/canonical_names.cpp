#include "ncbridge/canonical/call.hpp"

namespace ncbridge::canonical {

namespace {
template <class T> struct NameOf;
template <> struct NameOf<UseLengthUnits> { static constexpr std::string_view value = "USE_LENGTH_UNITS"; };
template <> struct NameOf<SetG5xOffset> { static constexpr std::string_view value = "SET_G5X_OFFSET"; };
template <> struct NameOf<SetG92Offset> { static constexpr std::string_view value = "SET_G92_OFFSET"; };
template <> struct NameOf<SetXyRotation> { static constexpr std::string_view value = "SET_XY_ROTATION"; };
template <> struct NameOf<SelectPlane> { static constexpr std::string_view value = "SELECT_PLANE"; };
template <> struct NameOf<SetTraverseRate> { static constexpr std::string_view value = "SET_TRAVERSE_RATE"; };
template <> struct NameOf<StraightTraverse> { static constexpr std::string_view value = "STRAIGHT_TRAVERSE"; };
template <> struct NameOf<SetFeedRate> { static constexpr std::string_view value = "SET_FEED_RATE"; };
template <> struct NameOf<SetFeedReference> { static constexpr std::string_view value = "SET_FEED_REFERENCE"; };
template <> struct NameOf<SetFeedMode> { static constexpr std::string_view value = "SET_FEED_MODE"; };
template <> struct NameOf<SetMotionControlMode> { static constexpr std::string_view value = "SET_MOTION_CONTROL_MODE"; };
template <> struct NameOf<SetNaivecamTolerance> { static constexpr std::string_view value = "SET_NAIVECAM_TOLERANCE"; };
template <> struct NameOf<SetCutterRadiusCompensation> { static constexpr std::string_view value = "SET_CUTTER_RADIUS_COMPENSATION"; };
template <> struct NameOf<StartCutterRadiusCompensation> { static constexpr std::string_view value = "START_CUTTER_RADIUS_COMPENSATION"; };
template <> struct NameOf<StopCutterRadiusCompensation> { static constexpr std::string_view value = "STOP_CUTTER_RADIUS_COMPENSATION"; };
template <> struct NameOf<StartSpeedFeedSynch> { static constexpr std::string_view value = "START_SPEED_FEED_SYNCH"; };
template <> struct NameOf<StopSpeedFeedSynch> { static constexpr std::string_view value = "STOP_SPEED_FEED_SYNCH"; };
template <> struct NameOf<ArcFeed> { static constexpr std::string_view value = "ARC_FEED"; };
template <> struct NameOf<StraightFeed> { static constexpr std::string_view value = "STRAIGHT_FEED"; };
template <> struct NameOf<StraightProbe> { static constexpr std::string_view value = "STRAIGHT_PROBE"; };
template <> struct NameOf<RigidTap> { static constexpr std::string_view value = "RIGID_TAP"; };
template <> struct NameOf<Dwell> { static constexpr std::string_view value = "DWELL"; };
template <> struct NameOf<SetSpindleSpeed> { static constexpr std::string_view value = "SET_SPINDLE_SPEED"; };
template <> struct NameOf<StartSpindleClockwise> { static constexpr std::string_view value = "START_SPINDLE_CLOCKWISE"; };
template <> struct NameOf<StartSpindleCounterclockwise> { static constexpr std::string_view value = "START_SPINDLE_COUNTERCLOCKWISE"; };
template <> struct NameOf<StopSpindleTurning> { static constexpr std::string_view value = "STOP_SPINDLE_TURNING"; };
template <> struct NameOf<SetSpindleMode> { static constexpr std::string_view value = "SET_SPINDLE_MODE"; };
template <> struct NameOf<OrientSpindle> { static constexpr std::string_view value = "ORIENT_SPINDLE"; };
template <> struct NameOf<SpindleRetract> { static constexpr std::string_view value = "SPINDLE_RETRACT"; };
template <> struct NameOf<UseToolLengthOffset> { static constexpr std::string_view value = "USE_TOOL_LENGTH_OFFSET"; };
template <> struct NameOf<SelectTool> { static constexpr std::string_view value = "SELECT_TOOL"; };
template <> struct NameOf<StartChange> { static constexpr std::string_view value = "START_CHANGE"; };
template <> struct NameOf<ChangeTool> { static constexpr std::string_view value = "CHANGE_TOOL"; };
template <> struct NameOf<ChangeToolNumber> { static constexpr std::string_view value = "CHANGE_TOOL_NUMBER"; };
template <> struct NameOf<Comment> { static constexpr std::string_view value = "COMMENT"; };
template <> struct NameOf<Message> { static constexpr std::string_view value = "MESSAGE"; };
template <> struct NameOf<FloodOn> { static constexpr std::string_view value = "FLOOD_ON"; };
template <> struct NameOf<FloodOff> { static constexpr std::string_view value = "FLOOD_OFF"; };
template <> struct NameOf<MistOn> { static constexpr std::string_view value = "MIST_ON"; };
template <> struct NameOf<MistOff> { static constexpr std::string_view value = "MIST_OFF"; };
template <> struct NameOf<EnableFeedOverride> { static constexpr std::string_view value = "ENABLE_FEED_OVERRIDE"; };
template <> struct NameOf<DisableFeedOverride> { static constexpr std::string_view value = "DISABLE_FEED_OVERRIDE"; };
template <> struct NameOf<EnableSpeedOverride> { static constexpr std::string_view value = "ENABLE_SPEED_OVERRIDE"; };
template <> struct NameOf<DisableSpeedOverride> { static constexpr std::string_view value = "DISABLE_SPEED_OVERRIDE"; };
template <> struct NameOf<EnableAdaptiveFeed> { static constexpr std::string_view value = "ENABLE_ADAPTIVE_FEED"; };
template <> struct NameOf<DisableAdaptiveFeed> { static constexpr std::string_view value = "DISABLE_ADAPTIVE_FEED"; };
template <> struct NameOf<EnableFeedHold> { static constexpr std::string_view value = "ENABLE_FEED_HOLD"; };
template <> struct NameOf<DisableFeedHold> { static constexpr std::string_view value = "DISABLE_FEED_HOLD"; };
template <> struct NameOf<OptionalProgramStop> { static constexpr std::string_view value = "OPTIONAL_PROGRAM_STOP"; };
template <> struct NameOf<ProgramStop> { static constexpr std::string_view value = "PROGRAM_STOP"; };
template <> struct NameOf<ProgramEnd> { static constexpr std::string_view value = "PROGRAM_END"; };
template <> struct NameOf<PalletShuttle> { static constexpr std::string_view value = "PALLET_SHUTTLE"; };
template <> struct NameOf<OnReset> { static constexpr std::string_view value = "ON_RESET"; };
template <> struct NameOf<WaitSpindleOrientComplete> { static constexpr std::string_view value = "WAIT_SPINDLE_ORIENT_COMPLETE"; };
template <> struct NameOf<Finish> { static constexpr std::string_view value = "FINISH"; };
template <> struct NameOf<SetToolTableEntry> { static constexpr std::string_view value = "SET_TOOL_TABLE_ENTRY"; };
template <> struct NameOf<NurbsFeed> { static constexpr std::string_view value = "NURBS_FEED"; };
template <> struct NameOf<TurnProbeOn> { static constexpr std::string_view value = "TURN_PROBE_ON"; };
template <> struct NameOf<TurnProbeOff> { static constexpr std::string_view value = "TURN_PROBE_OFF"; };
template <> struct NameOf<LogOpen> { static constexpr std::string_view value = "LOGOPEN"; };
template <> struct NameOf<LogAppend> { static constexpr std::string_view value = "LOGAPPEND"; };
template <> struct NameOf<LogClose> { static constexpr std::string_view value = "LOGCLOSE"; };
template <> struct NameOf<Log> { static constexpr std::string_view value = "LOG"; };
template <> struct NameOf<Print> { static constexpr std::string_view value = "PRINT"; };
}  // namespace

std::string_view name_of(const Data& data) {
  return std::visit([](const auto& d) { return NameOf<std::decay_t<decltype(d)>>::value; }, data);
}

}  // namespace ncbridge::canonical
