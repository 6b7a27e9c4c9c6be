#pragma once
// NIST canonical machining functions (RS274/NGC v3, section 4; LinuxCNC canon.hh), as values.
//
// This is THE seam between the interpreter and everything downstream: the interpreter (any
// dialect) emits a stream of ncbridge::canonical::Call into a Sink; the cc1_builder consumes it.
// Names follow the canonical function names so a reader can look them up. Lengths are in the
// units set by the latest USE_LENGTH_UNITS, angles in degrees, feed in units/min (G94),
// as LinuxCNC's canon layer receives them.
//
// Coordinates are absolute positions in the PROGRAM frame, as LinuxCNC's interpreter hands them
// to its canon layer (and as rs274 prints them): incremental words, G53 and unit changes are
// already resolved, but the work offset, the G92 offset, the XY rotation and the tool length
// offset are NOT applied. They are announced separately, when they change, by SET_G5X_OFFSET,
// SET_G92_OFFSET, SET_XY_ROTATION and USE_TOOL_LENGTH_OFFSET; the machine position of a point
// is the point rotated about the work origin by the XY rotation, plus the G5x and G92 offsets,
// plus the tool length offset.
//
// The wire form is proto/canonical.proto (see canonical/proto_codec.hpp).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace ncbridge::canonical {

// Where a call came from in the user's program.
struct Source {
  std::uint32_t file = 0;       // index into the stream's file table (Sink::source_file)
  std::uint32_t line = 0;       // 1-based line of the block; 0 = made by the interpreter itself
  std::int64_t n_number = -1;   // the block's N word, -1 when it has none
  std::uint8_t n_digits = 0;    // digits of the N word as written (keeps leading zeros), 0 = natural
};

// For calls produced by a canned cycle (G73, G81..G89): which cycle made them, with what.
// Positions (x, y, clearance, r, z; k for G87) are absolute program-frame coordinates in the
// current units, like the calls themselves (incremental words already resolved); q is a length.
struct CycleTag {
  std::uint32_t cycle_id = 0;   // 1, 2, ...: one per hole (each repeat of an L-repeat counts)
  std::uint16_t g_code_x10 = 0; // 730, 810, 820, 830, 840, 841 (G84.1? LinuxCNC: G74), 850..890
  bool retract_to_r = false;    // true for G99 (retract to R), false for G98 (to initial Z)
  std::uint8_t plane = 0;       // 0 = XY (G17), 1 = YZ (G19), 2 = XZ (G18)
  double x = 0, y = 0;          // hole position in the plane's first/second axes
  double clearance = 0;         // the initial (G98) level along the plane's normal axis
  double r = 0;                 // retract plane
  double z = 0;                 // hole bottom
  double q = 0;                 // peck increment (G73/G83), 0 when not given
  double p = 0;                 // dwell seconds (G82/G86/G88/G89), 0 when not given
  double k = 0;                 // G76-style extra parameter / thread pitch where a dialect has one
  std::uint32_t repeat = 1;     // L: number of repeats of this block
};

enum class Units : std::uint8_t { Inches, Millimeters };
enum class Plane : std::uint8_t { XY, YZ, XZ, UV, VW, UW };
enum class FeedReference : std::uint8_t { Workpiece, Xyz };
enum class MotionControlMode : std::uint8_t { ExactStop, ExactPath, Continuous };
enum class Side : std::uint8_t { Left, Right, Off };
enum class Direction : std::uint8_t { Stopped, Clockwise, Counterclockwise };

// Nine-axis position, as LinuxCNC passes it (x y z a b c u v w).
struct Pose {
  double x = 0, y = 0, z = 0, a = 0, b = 0, c = 0, u = 0, v = 0, w = 0;
  friend bool operator==(const Pose&, const Pose&) = default;
};

// ---- Representation
struct UseLengthUnits { Units units; };
struct SetG5xOffset { int index; Pose offset; };          // index 1..9 = G54..G59.3
struct SetG92Offset { Pose offset; };
struct SetXyRotation { double degrees; };
struct SelectPlane { Plane plane; };
struct SetTraverseRate { double rate; };

// ---- Free-space motion
struct StraightTraverse { Pose end; };

// ---- Machining attributes
struct SetFeedRate { double rate; };
struct SetFeedReference { FeedReference reference; };
struct SetFeedMode { int spindle; int mode; };             // 0 units/min, 1 inverse time, 2 per rev
struct SetMotionControlMode { MotionControlMode mode; double tolerance; };
struct SetNaivecamTolerance { double tolerance; };
struct SetCutterRadiusCompensation { double radius; };
struct StartCutterRadiusCompensation { Side side; };
struct StopCutterRadiusCompensation {};
struct StartSpeedFeedSynch { int spindle; double feed_per_revolution; bool velocity_mode; };
struct StopSpeedFeedSynch {};

// ---- Machining functions
// first/second: the plane's two axes (XY: x,y; YZ: y,z; XZ: z,x); axis_end_point along the normal.
// rotation: >0 counter-clockwise turns, <0 clockwise, |rotation| = number of turns (LinuxCNC).
struct ArcFeed {
  double first_end, second_end, first_axis, second_axis;
  int rotation;
  double axis_end_point;
  double a, b, c, u, v, w;
};
struct StraightFeed { Pose end; };
// A NURBS curve in the XY plane at the current Z (LinuxCNC NURBS_FEED, made by G5 cubic
// splines, G5.1 quadratic B-splines and G5.2/G5.3 NURBS): control points with weights, the
// first one the current position; `order` is the degree + 1. Its knot vector is implicit, the
// clamped uniform one of LinuxCNC (knot_vector_creator): `order` zeros, 1, 2, ..., n - order + 1,
// then `order` times n - order + 2, for control points 0..n.
struct NurbsControlPoint {
  double x, y, weight;
  friend bool operator==(const NurbsControlPoint&, const NurbsControlPoint&) = default;
};
struct NurbsFeed {
  std::vector<NurbsControlPoint> control_points;
  int order;
};
// G38.2-G38.5. probe_type, as LinuxCNC passes it: bit 0 set = no error when the move ends
// without the probe changing state (G38.3, G38.5), bit 1 set = move until the probe loses
// contact instead of until it touches (G38.4, G38.5).
struct StraightProbe {
  Pose end;
  std::uint8_t probe_type = 0;
};
struct RigidTap { Pose end; double scale; };
struct Dwell { double seconds; };

// ---- Spindle
struct SetSpindleSpeed { int spindle; double rpm; };
struct StartSpindleClockwise { int spindle; };
struct StartSpindleCounterclockwise { int spindle; };
struct StopSpindleTurning { int spindle; };
struct SetSpindleMode { int spindle; double css_maximum; };  // 0 = constant rpm
struct OrientSpindle { int spindle; double orientation; int mode; };
struct SpindleRetract {};
struct WaitSpindleOrientComplete { int spindle; double timeout; };  // M19 Q: seconds

// ---- Tool
struct UseToolLengthOffset { Pose offset; };
struct SelectTool { int tool; };
struct StartChange {};
struct ChangeTool { int slot; };  // LinuxCNC's pocket index of the selected tool (see SelectTool)
struct ChangeToolNumber {        // M61: the tool now in the spindle, without a change
  int number;                    // its tool number
  int pocket = 0;                // its pocket index (what LinuxCNC passes to CHANGE_TOOL_NUMBER)
};
// G10 L1/L10/L11 wrote a tool table entry: the pocket (LinuxCNC's index; 0 = the spindle), the
// tool number, its offsets and diameter (lengths in current units), lathe angles, orientation.
struct SetToolTableEntry {
  int pocket;
  int tool;
  Pose offset;
  double diameter, frontangle, backangle;
  int orientation;
};

// ---- Miscellaneous
struct Comment { std::string text; };
struct Message { std::string text; };
struct FloodOn {};
struct FloodOff {};
struct MistOn {};
struct MistOff {};
struct EnableFeedOverride { int spindle; };
struct DisableFeedOverride { int spindle; };
struct EnableSpeedOverride { int spindle; };
struct DisableSpeedOverride { int spindle; };
struct EnableAdaptiveFeed {};
struct DisableAdaptiveFeed {};
struct EnableFeedHold {};
struct DisableFeedHold {};

// Probing and operator output. TURN_PROBE_ON/OFF frame each STRAIGHT_PROBE. LOGOPEN/LOGAPPEND
// open (truncating or appending) the file a program's LOG lines are written to, LOGCLOSE closes
// it. PRINT is no NIST canonical function: LinuxCNC writes its text to the interpreter's standard
// output, and `ncbridge canon` prints it there, as a line of its own, as rs274 does.
struct TurnProbeOn {};
struct TurnProbeOff {};
struct LogOpen { std::string path; };
struct LogAppend { std::string path; };
struct LogClose {};
struct Log { std::string text; };
struct Print { std::string text; };

// ---- Program
struct OptionalProgramStop {};
struct ProgramStop {};
struct ProgramEnd {};
struct PalletShuttle {};
struct OnReset {};
struct Finish {};  // the closing `%` of a %-delimited program (LinuxCNC prints FINISH())

using Data = std::variant<
    UseLengthUnits, SetG5xOffset, SetG92Offset, SetXyRotation, SelectPlane, SetTraverseRate,
    StraightTraverse,
    SetFeedRate, SetFeedReference, SetFeedMode, SetMotionControlMode, SetNaivecamTolerance,
    SetCutterRadiusCompensation, StartCutterRadiusCompensation, StopCutterRadiusCompensation,
    StartSpeedFeedSynch, StopSpeedFeedSynch,
    ArcFeed, StraightFeed, StraightProbe, RigidTap, Dwell,
    SetSpindleSpeed, StartSpindleClockwise, StartSpindleCounterclockwise, StopSpindleTurning,
    SetSpindleMode, OrientSpindle, SpindleRetract,
    UseToolLengthOffset, SelectTool, StartChange, ChangeTool, ChangeToolNumber,
    Comment, Message, FloodOn, FloodOff, MistOn, MistOff,
    EnableFeedOverride, DisableFeedOverride, EnableSpeedOverride, DisableSpeedOverride,
    EnableAdaptiveFeed, DisableAdaptiveFeed, EnableFeedHold, DisableFeedHold,
    OptionalProgramStop, ProgramStop, ProgramEnd, PalletShuttle, OnReset,
    // appended later; new alternatives go at the end so existing indices stay put
    WaitSpindleOrientComplete, Finish, SetToolTableEntry, NurbsFeed,
    TurnProbeOn, TurnProbeOff, LogOpen, LogAppend, LogClose, Log, Print>;

struct Call {
  Data data;
  Source source;
  std::optional<CycleTag> cycle;  // set on every call a canned cycle made
};

// NIST name of a call, e.g. "STRAIGHT_FEED".
std::string_view name_of(const Data& data);

// Receives a canonical call stream. A stream announces each program file it reads from
// (index -> path) before the first call whose Source refers to it, then the calls in order,
// then end() once. Implementations: the rs274-format printer, the cc1_builder, the DDS
// batcher, test collectors.
class Sink {
 public:
  virtual ~Sink() = default;
  virtual void source_file(std::uint32_t /*index*/, std::string_view /*path*/) {}
  virtual void call(const Call& call) = 0;
  virtual void end() {}
};

}  // namespace ncbridge::canonical
