#pragma once
// The interpreter's own copy of the tool table (LinuxCNC's settings->tool_table): read from the
// tool list when the program starts, edited by G10 L1/L10/L11, read by G41/G42, G43 and the
// tool parameters. The caller's tool list is never changed.
//
// Pockets: LinuxCNC numbers the entries of its tool table 1, 2, ... in the order they are held
// (CHANGE_TOOL and SET_TOOL_TABLE_ENTRY print that index; 0 is the spindle). ncbridge's tool
// list is held sorted by tool number, so the indices agree with LinuxCNC's when the tool table
// file lists its tools by increasing T (as LinuxCNC's tool editor writes it).
#include <vector>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::interpreter {

struct ToolEntry {
  int number = 0;
  canonical::Pose offset_mm{};   // tool length offsets (x, y, z, u, v, w in mm; a, b, c degrees)
  double diameter_mm = 0;
  double frontangle = 0, backangle = 0;
  int orientation = 0;
  int listed = 0;  // position in the tool table as given, 0 for entries made by G10
};

class ToolTable {
 public:
  explicit ToolTable(const setup::ToolList& tools);

  const ToolEntry* find(int number) const;
  ToolEntry* find(int number);
  // The entry for `number`, made (all zero) when the table has none.
  ToolEntry& find_or_add(int number);
  // LinuxCNC's pocket index of a tool (non-random tool changer): its 1-based position in the
  // table file as listed, not sorted; for a tool the table does not hold, the tool number.
  int pocket_of(int number) const;
  bool empty() const { return entries_.empty(); }

 private:
  std::vector<ToolEntry> entries_;  // sorted by number
};

}  // namespace ncbridge::interpreter
