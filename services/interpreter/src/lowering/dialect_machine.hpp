#pragma once
// The machine every dialect front-end lowers onto: the shared parameter store, the RS274 block
// executor (modal state, units, work offsets, tool length, canned cycles, canonical output) and
// the dialect's programmable frame. A front-end evaluates its own syntax and control flow, then
// hands NeutralBlocks to execute(); positions it puts in them go through the frame first.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "block_command.hpp"
#include "block_model.hpp"
#include "executor.hpp"
#include "lowering/dialect_table.hpp"
#include "lowering/frame.hpp"
#include "lowering/line_segment.hpp"
#include "lowering/neutral_block.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "parameters.hpp"

namespace ncbridge::interpreter::lowering {

class DialectMachine {
 public:
  // `table`'s settings center_arc_radius_tolerance_mm/_inch, where given, replace LinuxCNC's
  // default arc end-radius tolerance (Executor::ArcTolerance).
  DialectMachine(const Options& options, canonical::Sink& sink, const DialectTable& table);
  DialectMachine(const DialectMachine&) = delete;
  DialectMachine& operator=(const DialectMachine&) = delete;

  const Options& options() const { return options_; }
  Parameters& parameters() { return params_; }
  const ModalState& state() const { return executor_.state(); }

  // Announces a program file to the sink (index -> path), before calls that refer to it.
  void announce_file(std::uint32_t index, const std::string& name) { sink_.source_file(index, name); }
  // The start-up calls (offsets, feed reference, ON_RESET), tagged with file 0.
  void start();
  // The block being lowered: every call and error from here on names it.
  void at(std::uint32_t file, const std::string& file_name, std::uint32_t line, std::int64_t n_number = -1,
          std::uint8_t n_digits = 0);

  // Runs one neutral block through the RS274 executor. True when it ended the program.
  bool execute(const NeutralBlock& block);
  // The blocks executed until end_spelled_hole() are one hole of a canned cycle the front-end
  // spells out as plain blocks (Executor::begin_spelled_hole).
  void begin_spelled_hole(const canonical::CycleTag& tag) { executor_.begin_spelled_hole(tag); }
  void end_spelled_hole() { executor_.end_spelled_hole(); }
  void comment(const std::string& text);  // a COMMENT call
  void message(const std::string& text);  // a MESSAGE call

  [[noreturn]] void fail(std::uint32_t column, const std::string& message) const;
  // A warning about the block being run (Options::warning); under Options::strict an error.
  void warn(std::uint32_t column, const std::string& message) const;
  // An M code of the machine builder (the table's machine_functions, Options::machine_functions):
  // a COMMENT and a warning naming the line (under --strict an error); false for any other code.
  bool machine_function(double code, std::uint32_t column);
  // The block being run was joined from these lines (set after at(), which clears it).
  void continued(std::vector<LineSegment> segments) { segments_ = std::move(segments); }

  // The tool number for a tool called by name (Siemens T="name", Heidenhain TOOL CALL "name"):
  // the tool list's tool of that name, else a number given in order of first use (said in a
  // COMMENT call, never silently).
  int tool_number_for_name(const std::string& name, std::uint32_t column);
  const std::string& file_name() const { return *file_name_; }
  std::uint32_t line() const { return line_; }

  // The programmable frame and the tool position seen through it (program units).
  Frame frame;
  Point3 position() const;
  // Appends X/Y/Z words that bring the tool to the given dialect-frame position; axes not
  // given keep their current dialect-frame value.
  void put_axes(NeutralBlock& block, std::optional<double> x, std::optional<double> y, std::optional<double> z,
                std::uint32_t column) const;
  // Appends G2/G3 with end point and I/J (incremental centre offsets, executor frame) for an arc
  // in the XY plane from the current position around the dialect-frame centre (cx, cy).
  void put_xy_arc(NeutralBlock& block, bool clockwise, std::optional<double> x, std::optional<double> y,
                  std::optional<double> z, double cx, double cy, std::uint32_t column) const;

 private:
  const Options& options_;
  canonical::Sink& sink_;
  Parameters params_;
  Executor executor_;
  Block block_;
  BlockCommand command_;
  std::vector<double> values_;
  canonical::Source source_;
  const std::string* file_name_;
  std::string no_file_;
  std::uint32_t line_ = 0;
  std::vector<std::string> unlisted_tool_names_;
  std::vector<LineSegment> segments_;
  std::map<std::string, std::string> machine_functions_;
};

}  // namespace ncbridge::interpreter::lowering
