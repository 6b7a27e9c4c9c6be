#pragma once
// One executed block of the ncbridge/blocks topic (proto/block.proto), and its codec.
#include <cstdint>
#include <string>
#include <string_view>

namespace ncbridge::wire {

enum class BlockKind : std::uint8_t { RunStart, Block, RunEnd };

struct ExecutedBlock {
  std::string controller_id;
  std::string run_id;
  std::uint64_t seq = 0;
  BlockKind kind = BlockKind::Block;
  std::string text;
  std::uint32_t line = 0;
  // RunStart: what the controller runs (proto/block.proto).
  std::string program_text;
  std::string tool_table;       // LinuxCNC .tbl lines, "" = none
  bool tool_table_inch = false;
  std::uint32_t start_line = 0;
  // RunEnd: a run stopped before the program's end.
  bool aborted = false;
  std::string reason;
  friend bool operator==(const ExecutedBlock&, const ExecutedBlock&) = default;
};

std::string encode_block(const ExecutedBlock& block);
ExecutedBlock decode_block(std::string_view bytes);  // throws InputError on malformed bytes

}  // namespace ncbridge::wire
