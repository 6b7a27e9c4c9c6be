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
  return m.SerializeAsString();
}

ExecutedBlock decode_block(std::string_view bytes) {
  using namespace detail;
  pb::ExecutedBlock m;
  parse_or_throw(m, bytes, "executed block");
  return {m.controller_id(), m.run_id(), m.seq(),
          enum_in_range<BlockKind>(m.kind(), 3, "executed block", "kind"), m.text(), m.line()};
}

}  // namespace ncbridge::wire
