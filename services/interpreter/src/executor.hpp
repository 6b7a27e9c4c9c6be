#pragma once
// The RS274 block executor: runs one BlockCommand against the modal state in the NIST order of
// execution (RS274/NGC v3 table 8; LinuxCNC execute_block), emitting canonical calls tagged
// with the block's Source. Phases live in files named for them: motion.cpp, arcs.cpp,
// canned_cycles.cpp, offsets.cpp, tools_and_spindle.cpp, program_end.cpp.
#include <optional>
#include <string>
#include <vector>

#include "block_command.hpp"
#include "cutter_compensation.hpp"
#include "modal_state.hpp"
#include "ncbridge/canonical/call.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "parameters.hpp"
#include "tool_table.hpp"

namespace ncbridge::interpreter {

class Executor final : public ComputedParameters {
 public:
  Executor(const Options& options, Parameters& parameters, canonical::Sink& sink);
  ~Executor() override;
  Executor(const Executor&) = delete;
  Executor& operator=(const Executor&) = delete;

  // The calls LinuxCNC makes when the interpreter starts (offsets, feed reference, ON_RESET).
  void start();

  // Runs one block. `source` tags every call it makes; `file` names the file for errors.
  // Returns true when the block ended the program (M2, M30).
  bool execute(const BlockCommand& block, const canonical::Source& source, const std::string& file);

  // Emits a call now (tagged with the current source).
  void emit(canonical::Data data);
  void set_source(const canonical::Source& source) { source_ = source; }
  // The program stopped without M2/M30 (end of file, closing `%`): LinuxCNC drops the move
  // cutter compensation still holds back.
  void end_of_file();

  // A canned cycle a dialect front-end spells out as plain blocks (Fanuc G76, G87): the calls of
  // the blocks executed until end_spelled_hole() are one hole's, tagged with `tag` (cycle_id is
  // numbered here, after the holes the executor's own cycles made).
  void begin_spelled_hole(canonical::CycleTag tag) {
    tag.cycle_id = ++s_.cycle_count;
    spelled_hole_ = tag;
  }
  void end_spelled_hole() { spelled_hole_.reset(); }

  const ModalState& state() const { return s_; }
  std::optional<double> computed(std::string_view name) const override;

  // The end-radius tolerance of IJK arcs, in mm and in inches (LinuxCNC's INI settings
  // [RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_MM/_INCH; a dialect's table may set its controller's).
  struct ArcTolerance {
    double mm = 2 * 0.01 * 1.4142135623730951;     // LinuxCNC's defaults: 2 * 0.01 * sqrt(2) mm
    double inch = 2 * 0.001 * 1.4142135623730951;  // and 2 * 0.001 * sqrt(2) in
  };
  void set_arc_tolerance(const ArcTolerance& tolerance) { arc_tolerance_ = tolerance; }

 private:
  [[noreturn]] void fail(std::uint32_t column, const std::string& message) const;
 public:
  // A warning about the block being run (Options::warning); with Options::strict an error.
  void warn(std::uint32_t column, const std::string& message) const;

 private:

  // executor.cpp
  void check_block(const BlockCommand& b);
  void do_comment(const BlockCommand& b);
  void do_feed_mode(int g);
  void do_feed_rate(const BlockCommand& b);
  void do_speed(const BlockCommand& b);
  void do_dwell(const BlockCommand& b);
  void do_plane(const BlockCommand& b, int g);
  void do_units(int g);
  void do_control_mode(const BlockCommand& b, int g);
  void do_distance_mode(int g);
  void do_retract_mode(int g);
  void do_overrides(const BlockCommand& b);
  void do_coolant(const BlockCommand& b);
  void do_wait_on_input(const BlockCommand& b);
  void do_cutter_comp(const BlockCommand& b, int g);
  double comp_radius_of_tool(const BlockCommand& b, int g);

  // tools_and_spindle.cpp
  void do_tool_select(const BlockCommand& b);
  void do_tool_change(const BlockCommand& b);
  void do_spindle(const BlockCommand& b);

  // modal_context.cpp: M70 save, M71 invalidate, M72 restore, M73 save and restore on return
 public:
  void enter_call();  // a subroutine call begins
  void leave_call();  // it returns (restores what M73 saved in it)
 private:
  void do_modal_context(const BlockCommand& b, int m);
  void restore_modal_state(const ModalState& saved);
  void do_spindle_mode(const BlockCommand& b, int g);
  void do_tool_length_offset(const BlockCommand& b, int g);
  void write_tool_parameters();
  const ToolEntry* tool_entry(int number) const { return number == 0 ? nullptr : tools_.find(number); }

  // offsets.cpp
  void do_coordinate_system(int g, std::uint32_t column);
  void do_g10(const BlockCommand& b);
  void do_g10_tool(const BlockCommand& b, int l);
  void do_home(const BlockCommand& b, int g);
  void do_axis_offsets(const BlockCommand& b, int g);
  void apply_origin_change(const canonical::Pose& old_total_mm);
  canonical::Pose origin_mm() const;  // g5x + g92 (when active)
  canonical::Pose current_in_system(int system) const;  // LinuxCNC find_current_in_system
  void emit_g5x();
  void emit_g92();
  void write_parameters();
  void write_position_parameters();

  // motion.cpp
  void do_motion(const BlockCommand& b, int motion, bool g53);
  canonical::Pose find_end(const BlockCommand& b, bool g53) const;
  canonical::Pose polar_end(const BlockCommand& b, canonical::Pose end, bool g53) const;
  void straight(bool feed, const canonical::Pose& end, const BlockCommand* b);
  void set_inverse_time_rate(double length, const BlockCommand& b);

  // arcs.cpp
  void arc(const BlockCommand& b, int motion, const canonical::Pose& end);

  // splines.cpp
  void spline(const BlockCommand& b, int motion);
  void nurbs_point(const BlockCommand& b);
  void nurbs_end(const BlockCommand& b);

  // probing.cpp
  void probe(const BlockCommand& b, int motion);

  // canned_cycles.cpp
  void canned_cycle(const BlockCommand& b, int motion);

  // program_end.cpp
  bool do_stop(const BlockCommand& b);

  double to_units(double mm) const { return mm / s_.mm_per_unit(); }
  // LinuxCNC's (int)(v + 0.5), saturated instead of undefined for values no int holds.
  static int nearest_int(double v) {
    const double t = v + 0.5;
    if (!(t > -2147483648.0)) return -2147483647 - 1;
    if (!(t < 2147483647.0)) return 2147483647;
    return static_cast<int>(t);
  }
  canonical::Pose to_units(const canonical::Pose& mm) const;

  const Options& options_;
  ArcTolerance arc_tolerance_;
  Parameters& params_;
  canonical::Sink& sink_;
  ModalState s_;
  canonical::Source source_;
  std::optional<canonical::CycleTag> cycle_tag_;
  std::optional<canonical::CycleTag> spelled_hole_;  // begin_spelled_hole()
  const std::string* file_ = nullptr;
  std::uint32_t line_ = 0;

  // Cutter radius compensation (G41/G42): while active, moves go through it as programmed
  // geometry and every other call through comp_.other(), which holds back what LinuxCNC holds
  // back behind the pending move. s_.position stays the programmed point.
  ToolTable tools_;               // the program's copy, edited by G10 L1/L10/L11
  bool tool_table_given_ = false; // without a table any tool number is accepted
  bool warned_no_tool_length_ = false;  // G43 without a tool list: said once
  int current_pocket_ = 1;        // LinuxCNC's pocket of the loaded tool (rs274 starts at 1)
  ToolEntry spindle_tool_{};      // pocket 0: the loaded tool's data as M6 copied it (G41/G42
                                  // without D, #5400-#5413); M61 does not copy, G10 L1 updates it

  struct SavedContext {
    ModalState state;
    bool valid = false;
    bool restore_on_return = false;
  };
  std::vector<SavedContext> contexts_ = std::vector<SavedContext>(1);  // one per call level

  // The compensator works in the XY plane. In the XZ plane (G18) it is given Z as X and X as Y
  // (and Y as Z), which is also how ARC_FEED names the XZ plane's axes, and this sink turns the
  // straight moves it makes back.
  class CompPlaneSink final : public canonical::Sink {
   public:
    explicit CompPlaneSink(canonical::Sink& out) : out_(out) {}
    void call(const canonical::Call& call) override;
    bool xz = false;

   private:
    canonical::Sink& out_;
  };
  static canonical::Pose xz_to_comp(const canonical::Pose& p) { return {p.z, p.x, p.y, p.a, p.b, p.c, p.u, p.v, p.w}; }
  static canonical::Pose comp_to_xz(const canonical::Pose& p) { return {p.y, p.z, p.x, p.a, p.b, p.c, p.u, p.v, p.w}; }
  canonical::Pose to_comp(const canonical::Pose& p) const { return comp_out_.xz ? xz_to_comp(p) : p; }
  canonical::Pose from_comp(const canonical::Pose& p) const { return comp_out_.xz ? comp_to_xz(p) : p; }
  CompPlaneSink comp_out_;
  CutterCompensation comp_;
  std::uint32_t comp_column_ = 0;  // column of the block's motion code, for comp errors
  bool comp_moved_ = false;        // a move was made with compensation on (radius > 0)
  bool arc_not_allowed_ = false;   // just after G40: the next move must be straight

  // G5.2 control points so far and the curve's order (LinuxCNC keeps them outside the modal
  // state: M70-M73 do not save them).
  std::vector<canonical::NurbsControlPoint> nurbs_points_;
  int nurbs_order_ = 3;
};

}  // namespace ncbridge::interpreter
