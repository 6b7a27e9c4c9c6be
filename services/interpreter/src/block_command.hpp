#pragma once
// One RS274 block after evaluation: the value of each word, the G codes by modal group and the
// M codes by group, checked for modal-group violations and repeated words. This is what the
// executor runs (LinuxCNC's block_struct, without the parsing state).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "block_model.hpp"

namespace ncbridge::interpreter {

// G-code modal groups (RS274/NGC v3 table 4, LinuxCNC numbering).
enum GroupG : int {
  kGNonModal = 0, kGMotion = 1, kGPlane = 2, kGDistance = 3, kGArcDistance = 4, kGFeedMode = 5,
  kGUnits = 6, kGCutterComp = 7, kGToolLength = 8, kGRetract = 10, kGCoordSystem = 12,
  kGControl = 13, kGSpindleMode = 14, kGLatheDiameter = 15, kGGroupCount = 16
};
// M-code groups.
enum GroupM : int {
  kMStop = 4, kMInput = 5, kMToolChange = 6, kMSpindle = 7, kMCoolant = 8, kMOverride = 9, kMUser = 10,
  kMGroupCount = 11
};

struct BlockCommand {
  std::array<double, 26> value{};
  std::array<std::uint32_t, 26> column{};
  std::uint32_t present = 0;  // bit (letter - 'a')

  std::array<int, kGGroupCount> g{};   // G number x10 per group, -1 when absent
  std::array<std::uint32_t, kGGroupCount> g_column{};
  std::array<int, kMGroupCount> m{};   // M number per group, -1 when absent
  std::array<std::uint32_t, kMGroupCount> m_column{};
  bool mist_on = false, flood_on = false;  // M7 and M8 may share a block

  // Polar coordinates (`@` radius, `^` angle in degrees; LinuxCNC allows each more than once,
  // the last one counts).
  bool has_polar_radius = false, has_polar_angle = false;
  double polar_radius = 0, polar_angle = 0;
  std::uint32_t polar_radius_column = 0, polar_angle_column = 0;
  bool has_polar() const { return has_polar_radius || has_polar_angle; }
  std::uint32_t polar_column() const { return has_polar_radius ? polar_radius_column : polar_angle_column; }

  std::string_view comment;       // the last plain comment of the line
  bool comment_is_message = false;
  // What the comment asks for beyond a COMMENT call (set by the control-flow runner for
  // LinuxCNC's active comments; `comment` then holds the text to print or log).
  enum class CommentAction : std::uint8_t { Comment, Print, Log, LogOpen, LogAppend, LogClose, Nothing };
  CommentAction comment_action = CommentAction::Comment;
  std::uint32_t line = 0;

  bool has(char letter) const { return (present >> (letter - 'a')) & 1u; }
  double get(char letter) const { return value[static_cast<std::size_t>(letter - 'a')]; }
  std::uint32_t col(char letter) const { return column[static_cast<std::size_t>(letter - 'a')]; }
  bool has_axis() const;
  void reset();
};

// Word values evaluated in word order (values[i] belongs to block.words[i]).
// Throws InputError for unknown codes, two codes of one modal group, repeated words.
void assemble_command(const Block& block, const double* values, const std::string& file, BlockCommand& out);

}  // namespace ncbridge::interpreter
