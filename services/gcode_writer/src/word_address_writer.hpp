#pragma once
// The writer of word-address dialects (RS274/NGC, Fanuc, Mach3, SINUMERIK 840D): blocks of
// words. A block holds words in the interpreter's order of execution (RS274/NGC table 8: F, S,
// T, M6, M3, M8, G4, G17, G20, G43, G54, G61, G98, G10/G92, motion, M0/M2), so the words of
// consecutive calls share a block only when the reader runs them in the order they came.
// What differs between the dialects is in the hooks; RS274/NGC (LinuxCNC) is the default.
#include <initializer_list>
#include <map>
#include <string>

#include "cycle_motion.hpp"
#include "dialect_writer.hpp"
#include "number_format.hpp"

namespace ncbridge::gcode_writer {

// Comment text the dialect's comment delimiters can hold: `open` and `close` become [ ], line
// breaks blanks.
std::string sanitize(std::string_view text, char open, char close);
// Pieces of text joined (without the temporaries of "a" + b + "c").
inline std::string concat(std::initializer_list<std::string_view> pieces) {
  std::string s;
  std::size_t n = 0;
  for (std::string_view p : pieces) n += p.size();
  s.reserve(n);
  for (std::string_view p : pieces) s += p;
  return s;
}
// `prefix` and an integer: "T" 12 -> T12.
inline void append_int(std::string& s, std::string_view prefix, long long n) {
  s += prefix;
  char digits[24];
  int len = 0;
  const bool negative = n < 0;
  unsigned long long u = negative ? 0ull - static_cast<unsigned long long>(n) : static_cast<unsigned long long>(n);
  do {
    digits[len++] = static_cast<char>('0' + u % 10);
    u /= 10;
  } while (u != 0);
  if (negative) s.push_back('-');
  while (len > 0) s.push_back(digits[--len]);
}
inline std::string number_text(long long n) {
  std::string s;
  append_int(s, "", n);
  return s;
}

class WordAddressWriter : public DialectWriter {
 public:
  WordAddressWriter(const Options& options, TextOutput& out, const WriterLocation& where);

  void begin_program(const MachineState& desired) override;
  void sync(const MachineState& desired, unsigned need) override;
  void traverse(const canonical::Pose& end) override;
  void feed(const canonical::Pose& end) override;
  void arc(const canonical::ArcFeed& arc) override;
  void dwell(double seconds) override;
  void tool_change(int tool) override;
  void action(const canonical::Call& call, const MachineState& desired) override;
  bool cycle(const Hole& hole, const MachineState& desired) override;
  void comment(std::string_view text) override;
  void message(std::string_view text) override;
  void program_end(bool rewind) override;
  void end_program(bool ended) override;
  void begin_repeat(std::uint32_t count, double z_shift) override;
  void end_repeat() override;

 protected:
  // Word groups in the reader's order of execution.
  enum class Slot : std::uint8_t {
    Comment, SpindleMode, FeedMode, Feed, Speed, Tool, ToolChange, Spindle, Coolant, Override, Dwell,
    Plane, Units, ToolLength, CoordSystem, Control, Distance, Retract, NonModal, Motion, Stop, Count
  };
  // The text of `slot` in the block being made (a new block when the slot is taken or comes
  // before one already used): append the words to the returned string. A block is printed
  // with its G words first, then the motion, then F S T and the M words (as programmers write).
  std::string& put(Slot slot);
  void flush();  // ends the block being made
  // A whole line of its own (comments, program frame), after the block being made.
  void line(std::string_view text);

  void append(std::string& s, char letter, double value);        // a length in current units
  void append_feed(std::string& s, char letter, double value);
  void append_plain(std::string& s, char letter, double value);  // angles, seconds, counts
  double length(double value) const { return rounded(value, length_decimals()); }
  canonical::Pose rounded_pose(const canonical::Pose& pose) const;

  [[noreturn]] void cannot(const std::string& construct, const std::string& why = {}) const { refuse(construct, why); }
  // (761 and 871: Fanuc's G76 and G87, which its front-end spells as moves)
  bool is_cycle_motion(int motion) const {
    return motion == 730 || motion == 740 || (motion >= 810 && motion <= 890) || motion == 761 || motion == 871;
  }
  void leave_cycles();
  void axis_words(std::string& s, const canonical::Pose& end, bool always_one);
  void motion_word(std::string& s, int motion);  // G0/G1/G2/G3 when the reader is not in it

  // ---- hooks: RS274/NGC by default
  virtual void write_header();
  virtual void write_safety_block(const MachineState& desired);
  virtual void write_footer(bool ended);
  virtual void write_comment_line(std::string_view text);
  virtual void write_message_line(std::string_view text);
  virtual std::string_view units_word(canonical::Units units) const;
  virtual std::string_view plane_word(canonical::Plane plane) const;
  virtual std::string coord_system_word(int index) const;  // empty: the dialect has no such system
  virtual void sync_offsets(const MachineState& desired);
  virtual bool has_g92_clear() const { return true; }  // G92.1
  virtual void sync_tool_length(const MachineState& desired);
  virtual void sync_spindle_mode(const MachineState& desired);
  virtual void sync_control(const MachineState& desired);
  void sync_control_mode(canonical::MotionControlMode mode, double tolerance, double naive);
  virtual std::string_view control_word(canonical::MotionControlMode mode) const;
  // For a dialect without G64 P: the mode without the tolerance when Options::drop_path_tolerance
  // allows it (said once in a comment), else a refusal.
  void sync_control_without_tolerance(const MachineState& desired);
  bool said_dropped_ = false;
  virtual void sync_overrides(const MachineState& desired);
  virtual void write_dwell(double seconds);
  virtual void write_turns(std::string& s, int turns);  // an arc of more than one turn
  virtual bool axis_supported(char letter) const;
  virtual void write_tool_change(int tool);
  virtual void write_other_action(const canonical::Call& call, const MachineState& desired);
  // Which canned cycles the dialect has (G code x 10), and how P is written.
  virtual bool has_cycle(int motion) const;
  // Whether the dialect's cycle block reads P (the dwell) for this cycle; where it does not and
  // the cycle dwells anyway, the reader uses the P of an earlier cycle block of the same run.
  virtual bool reads_cycle_dwell(int motion) const;
  virtual void append_cycle_dwell(std::string& s, double seconds);
  virtual void write_repeat_begin(std::uint32_t count);
  virtual void write_repeat_end();

  // tool offsets (mm) of the reader's tool table: the tool list, then what G10 L1 wrote
  std::map<int, canonical::Pose> tool_offsets_mm_;
  // the frame generations (MachineState::frame_generation) of the last frame sync
  std::uint64_t synced_desired_frame_ = ~0ull, synced_reader_frame_ = ~0ull;
  const canonical::Pose* tool_offset_of(int tool) const;
  int tool_with_offset(const canonical::Pose& offset_mm, int prefer) const;

  TextOutput* target_;    // out_, or a subprogram's text (the repeat construct on Fanuc/Mach3)
  NumberStyle style_;     // lengths: decimals set by the units
  CycleReader cycle_;     // the reader's motion mode and canned-cycle state
  bool retract_written_ = false;  // G98/G99 written once (then only when it changes)
  double run_p_ = 0;              // the P of the running cycles, as the front-end keeps it
  bool point_always_ = false;
  bool numbered_ = false;
  std::uint64_t block_number_ = 0;
  std::string slot_text_[static_cast<int>(Slot::Count)];  // the block being made, by slot
  bool block_open_ = false;
  int last_slot_ = -1;
  std::uint32_t used_ = 0;
  bool incremental_ = false;          // inside a repeated body: coordinates relative to the reader
  canonical::Pose repeat_start_{};
  std::uint32_t repeat_count_ = 0;
  double repeat_shift_ = 0;
  int repeat_label_ = 0;
  std::optional<canonical::SetToolTableEntry> last_entry_;  // for the reader's pocket-0 echo
};

}  // namespace ncbridge::gcode_writer
