#include "tool_table.hpp"

#include <algorithm>

namespace ncbridge::interpreter {

namespace {
bool before(const ToolEntry& entry, int number) { return entry.number < number; }
}  // namespace

ToolTable::ToolTable(const setup::ToolList& tools) {
  entries_.reserve(tools.tools().size());
  for (const setup::Tool& t : tools.tools()) {
    ToolEntry e;
    e.number = t.number;
    e.offset_mm.x = t.x_offset;
    e.offset_mm.z = t.length;
    e.diameter_mm = t.diameter;
    e.listed = t.listed;
    entries_.push_back(e);
  }
}

const ToolEntry* ToolTable::find(int number) const {
  auto it = std::lower_bound(entries_.begin(), entries_.end(), number, before);
  return it != entries_.end() && it->number == number ? &*it : nullptr;
}

ToolEntry* ToolTable::find(int number) {
  return const_cast<ToolEntry*>(static_cast<const ToolTable&>(*this).find(number));
}

ToolEntry& ToolTable::find_or_add(int number) {
  auto it = std::lower_bound(entries_.begin(), entries_.end(), number, before);
  if (it != entries_.end() && it->number == number) return *it;
  ToolEntry e;
  e.number = number;
  return *entries_.insert(it, e);
}

int ToolTable::pocket_of(int number) const {
  auto it = std::lower_bound(entries_.begin(), entries_.end(), number, before);
  if (it != entries_.end() && it->number == number && it->listed > 0) return it->listed;
  return number;
}

}  // namespace ncbridge::interpreter
