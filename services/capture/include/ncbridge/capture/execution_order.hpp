#pragma once
// The order in which a controller executes a program's blocks: its control flow run (loops,
// branches, subroutine calls) as our interpreter runs it. Live capture publishes blocks in this
// order, and an adapter that sees only the line motion is on (LinuxCNC's motion_line, an
// MTConnect LineNumber) fills in the blocks it did not see from it.
#include <cstdint>
#include <string>
#include <vector>

#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::capture {

// One block as the controller executes it.
struct ExecutedLine {
  std::uint32_t line = 0;  // 1-based line in the program
  std::string text;        // the block (a subroutine call with arguments: "#1=[..] #2=[..]")
  bool moves = false;      // the block makes a motion (traverse, feed, arc, probe)
  friend bool operator==(const ExecutedLine&, const ExecutedLine&) = default;
};

// RS274/NGC: the program run with its control flow, without the o-word lines that steer it (a
// block in a loop once per pass, a subroutine's blocks at each call). Other dialects: the
// program's non-blank lines as written (their control flow is not expanded). Throws InputError
// where the interpreter refuses the program.
std::vector<ExecutedLine> execution_order(const std::string& program_name, const std::string& text,
                                          const setup::ToolList& tools,
                                          interpreter::Dialect dialect = interpreter::Dialect::Rs274Ngc);

}  // namespace ncbridge::capture
