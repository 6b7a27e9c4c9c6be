#pragma once
// What a program is written with: the target dialect and how its text looks (docs/gcode.md).
#include <cstdint>
#include <optional>
#include <string>

#include "ncbridge/gcode_writer/dialect.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::gcode_writer {

enum class Comments {
  None,     // no comments at all
  Program,  // the program's own comments (COMMENT and MESSAGE calls); the default
  Source,   // those, and before the blocks of each source line a comment naming it
            // (file:line, or the workingstep of a STEP-NC file)
};

struct Options {
  Dialect dialect = Dialect::Rs274Ngc;
  // The tools the written program runs with (the reader's tool table): a length offset is
  // written as G43 H<tool> (TOOL CALL, D1) when it is that tool's length.
  setup::ToolList tools;
  // Fanuc/Mach3 O number (main program), and the first number of the subprograms the repeat
  // construct makes; Heidenhain's and Siemens' program name.
  std::uint32_t program_number = 1000;
  std::string program_name = "NCBRIDGE";
  // Digits after the decimal point for lengths in mm (one more in inches); unset: the
  // dialect's own (4 everywhere: 0.1 um, the finest input increment of the controls).
  std::optional<int> decimals;
  // N words: unset = the dialect's habit (Fanuc, Siemens: N10, N20, ...; RS274/NGC and Mach3:
  // none). Heidenhain blocks are always numbered 0, 1, 2, ... (the control needs them).
  std::optional<bool> block_numbers;
  std::uint32_t block_number_step = 10;
  Comments comments = Comments::Program;
  // G64 P (LinuxCNC's path blending tolerance, a setting of its trajectory planner): a dialect
  // without it refuses it, unless this is set; then it writes its own continuous mode (Fanuc,
  // Mach3 G64, SINUMERIK G64, Heidenhain's default) and says so in a comment.
  bool drop_path_tolerance = false;
};

}  // namespace ncbridge::gcode_writer
