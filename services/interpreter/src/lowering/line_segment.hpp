#pragma once
// A block written over several lines (Heidenhain `~`) is read as one joined text; errors about
// it name the line and column each part came from.
#include <cstdint>
#include <string>
#include <vector>

#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter::lowering {

// The part of the joined text from `offset` (0-based) on comes from line `line`, where it starts
// at column `column` (1-based).
struct LineSegment {
  std::uint32_t offset = 0, line = 0, column = 1;
};

// The place of 1-based `column` of a joined block (no segments: a block of one line). Every
// place names a line and a column: before any block (an empty file) it is line 1, and an error
// about a whole block is at its column 1.
inline SourceLocation locate(const std::string& file, std::uint32_t line, std::uint32_t column,
                             const std::vector<LineSegment>& segments) {
  SourceLocation where{file, line == 0 ? 1 : line, column == 0 ? 1 : column};
  if (column == 0) return where;
  for (const LineSegment& s : segments) {
    if (s.offset + 1 > column) break;
    where.line = s.line;
    where.column = column - s.offset - 1 + s.column;
  }
  return where;
}

}  // namespace ncbridge::interpreter::lowering
