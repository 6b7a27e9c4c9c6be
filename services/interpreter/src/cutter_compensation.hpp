#pragma once
// Cutter radius compensation (G41/G42/G40) for the RS274/NGC executor, call for call as
// LinuxCNC 2.9 does it (interp_convert.cc convert_*_comp1/comp2, interp_queue.cc).
//
// NOTE FOR THE EXECUTOR ("interp"):
//  * Tell the compensator where the tool is with set_position() while compensation is off
//    (at least before each start()). Route USE_LENGTH_UNITS through other() (or call
//    set_length_units) so it knows the units: G20/G21 while compensation is on rescales the
//    queued moves, the positions and the radius, as LinuxCNC does.
//  * start(side, radius, source) is G41/G42 (radius = D diameter / 2 in current units; a
//    negative radius swaps the side). It emits COMMENT("interpreter: cutter radius
//    compensation on left|right") itself; stop(source) is G40 and emits the "off" comment.
//    Do not emit those comments yourself. start() throws if compensation is already on.
//    The plane check (XY only; LinuxCNC: "Cutter radius compensation allowed only in XY, XZ
//    planes") and the D-word/tool-table checks stay in the executor.
//  * While active(): pass every straight move (G0/G1) with its PROGRAMMED end to straight(),
//    every G2/G3 in the XY plane to arc() with its programmed end and the centre computed from
//    programmed_position() (IJK/R exactly as without compensation), and every other canonical
//    call to other(); other() queues what LinuxCNC queues (feed, dwell, spindle, coolant,
//    comments) behind the pending move and passes everything else straight through.
//    other() may also be used while compensation is off: it then just forwards.
//  * Before PROGRAM_STOP / OPTIONAL_PROGRAM_STOP / PALLET_SHUTTLE / PROGRAM_END (M0 M1 M60 M2
//    M30) call flush(); at M2/M30 then call reset() (LinuxCNC turns compensation off there
//    without a comment and without a G40 exit). When the file ends without M2/M30 (or with
//    `%`), LinuxCNC drops the pending move: call reset() without flush().
//  * Incremental moves and omitted axes while active are relative to programmed_position(),
//    not to position(). After stop() (G40) LinuxCNC continues from the PROGRAMMED point: take
//    programmed_position() as the executor's current point. position() is where the tool
//    actually is (end of the last compensated move).
//  * After G40 the next motion must be straight: LinuxCNC's "The move just after exiting
//    cutter compensation mode must be straight, not an arc" check is the executor's.
//  * Errors throw ncbridge::InputError at the location `locate(source)` of the move (or G40/M
//    block) being converted, with LinuxCNC's message text.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter {

class CutterCompensation {
 public:
  // Turns a call's Source into a place in the user's program (file name, line, column).
  // Without one, errors carry the line only.
  using Locate = std::function<SourceLocation(const canonical::Source&)>;

  explicit CutterCompensation(canonical::Sink& out, Locate locate = {},
                              canonical::Units units = canonical::Units::Millimeters);

  // Where the tool is while compensation is off (actual == programmed).
  void set_position(const canonical::Pose& position);
  // Units of all lengths from now on; rescales when compensation is on (LinuxCNC qc_scale).
  void set_length_units(canonical::Units units);

  void start(canonical::Side side, double radius, const canonical::Source& source = {});
  void stop(const canonical::Source& source = {});
  bool active() const { return side_ != canonical::Side::Off; }
  canonical::Side side() const { return side_; }
  double radius() const { return radius_; }

  // G0 (feed = false) or G1 to a programmed end point.
  void straight(bool feed, const canonical::Pose& programmed_end, const canonical::Source& source);
  // G2/G3 in the XY plane: first/second = X/Y, axis_end_point = Z, centre in first/second_axis.
  void arc(const canonical::ArcFeed& programmed_arc, const canonical::Source& source);
  void other(const canonical::Call& call);

  // Emits everything queued (LinuxCNC: move_endpoint_and_flush to the current point).
  void flush();
  // Compensation off without a G40 exit move; whatever is still queued is dropped (call
  // flush() first to keep it, as M2/M30 do).
  void reset();

  canonical::Pose position() const { return current_; }
  canonical::Pose programmed_position() const { return programmed_; }

 private:
  struct Queued {
    canonical::Call call;
    double dx = 0, dy = 0;        // straight moves: direction of the original motion
    double original_turns = 0;    // arcs: sweep in radians when queued, 0 = never checked
  };

  void straight_first(bool feed, const canonical::Pose& end, const canonical::Source& source);
  void straight_next(bool feed, const canonical::Pose& end, const canonical::Source& source);
  void arc_first(const canonical::ArcFeed& arc, const canonical::Source& source);
  void arc_next(const canonical::ArcFeed& arc, const canonical::Source& source);

  void enqueue_straight(bool feed, double dx, double dy, const canonical::Pose& end,
                        const canonical::Source& source);
  void enqueue_arc(double original_turns, const canonical::ArcFeed& arc, const canonical::Source& source);
  void move_endpoint_and_flush(double x, double y, const canonical::Source& source);
  void dequeue();
  void set_endpoint(double x, double y);
  const Queued* front_motion() const;
  void scale(double factor);
  void emit(const canonical::Call& call);
  [[noreturn]] void fail(const canonical::Source& source, std::string message) const;

  canonical::Sink& out_;
  Locate locate_;
  canonical::Units units_;
  canonical::Side side_ = canonical::Side::Off;
  double radius_ = 0;
  bool first_move_ = true;
  canonical::Pose current_;     // actual tool position
  canonical::Pose programmed_;  // last programmed point
  std::vector<Queued> queue_;
  std::optional<Queued> last_front_;  // what LinuxCNC's qc().front() reads on an empty queue
  double endpoint_x_ = 0, endpoint_y_ = 0;
  bool endpoint_valid_ = false;
};

}  // namespace ncbridge::interpreter
