#pragma once
// Fanuc 0i/18i/30i milling, and Mach3/Mach4 which read the same words with fewer features
// (services/interpreter/dialects/fanuc.yaml, mach3.yaml): the word-address writer with what
// the two controls have and lack.
#include "word_address_writer.hpp"

namespace ncbridge::gcode_writer {

class FanucWriter : public WordAddressWriter {
 public:
  FanucWriter(const Options& options, TextOutput& out, const WriterLocation& where, bool mach3);

  void end_program(bool ended) override;
  bool arcs_turn_more_than_once() const override { return false; }

 protected:
  void write_header() override;
  void write_footer(bool ended) override;
  void write_message_line(std::string_view text) override;
  std::string_view plane_word(canonical::Plane plane) const override;
  std::string coord_system_word(int index) const override;
  void sync_offsets(const MachineState& desired) override;
  bool has_g92_clear() const override { return false; }
  void sync_tool_length(const MachineState& desired) override;
  void sync_spindle_mode(const MachineState& desired) override;
  void sync_control(const MachineState& desired) override;
  void sync_overrides(const MachineState& desired) override;
  void write_dwell(double seconds) override;
  void write_turns(std::string& s, int turns) override;
  bool axis_supported(char letter) const override;
  void write_other_action(const canonical::Call& call, const MachineState& desired) override;
  bool has_cycle(int motion) const override;
  bool cycle(const Hole& hole, const MachineState& desired) override;
  // Fanuc's G76 (fine boring) and G87 (back boring), which its front-end spells as moves with an
  // oriented spindle stop (services/interpreter/src/fanuc/boring_cycles.cpp)
  bool fanuc_boring(const Hole& hole, const MachineState& desired);
  double fanuc_initial_ = 0;  // the front-end's initial level (set entering a run of cycles)
  bool reads_cycle_dwell(int motion) const override;
  void append_cycle_dwell(std::string& s, double seconds) override;
  void write_repeat_begin(std::uint32_t count) override;
  void write_repeat_end() override;

  bool mach3_;
  std::string subprograms_;         // the repeat construct's bodies, written after the main program
  std::unique_ptr<TextOutput> sub_out_;
};

}  // namespace ncbridge::gcode_writer
