#include "ncbridge/wire/block.hpp"

#include "block.pb.h"
#include "parse_or_throw.hpp"

namespace ncbridge::wire {

std::string encode_block(const ExecutedBlock& block) {
  pb::ExecutedBlock m;
  m.set_controller_id(block.controller_id);
  m.set_run_id(block.run_id);
  m.set_seq(block.seq);
  m.set_kind(static_cast<pb::BlockKind>(block.kind));
  m.set_text(block.text);
  m.set_line(block.line);
  m.set_program_text(block.program_text);
  m.set_tool_table(block.tool_table);
  m.set_tool_table_inch(block.tool_table_inch);
  m.set_start_line(block.start_line);
  m.set_aborted(block.aborted);
  m.set_reason(block.reason);
  return m.SerializeAsString();
}

ExecutedBlock decode_block(std::string_view bytes) {
  using namespace detail;
  pb::ExecutedBlock m;
  parse_or_throw(m, bytes, "executed block");
  ExecutedBlock b{m.controller_id(), m.run_id(), m.seq(),
                  enum_in_range<BlockKind>(m.kind(), 3, "executed block", "kind"), m.text(), m.line()};
  b.program_text = m.program_text();
  b.tool_table = m.tool_table();
  b.tool_table_inch = m.tool_table_inch();
  b.start_line = m.start_line();
  b.aborted = m.aborted();
  b.reason = m.reason();
  return b;
}

}  // namespace ncbridge::wire
