#pragma once
// Writes a Graph as an ISO 10303-21 exchange structure. Deterministic: the same graph and options
// give the same bytes. Reals are printed shortest-round-trip in Part 21 syntax (5. -0.5 1.E-05),
// strings escaped ('' \\ \X2\..\X0\), lines wrapped near `line_width`.
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

#include "ncbridge/step_writer/part21_graph.hpp"

namespace ncbridge::step_writer::part21 {

struct WriteOptions {
  // Renumber instances 1..n in graph order (references follow). Off: ids are written as they are.
  bool renumber = false;
  // Soft limit: an instance longer than this is broken after a comma; 0 = never wrap.
  std::size_t line_width = 100;
  // FILE_NAME time stamp when the header has none. Unset: SOURCE_DATE_EPOCH, else the clock.
  std::optional<std::int64_t> unix_time;
};

// Throws std::invalid_argument for graphs that cannot be written (reserved but unset instances,
// NaN/infinite reals, references to ids not in the graph).
std::string write_part21(const Graph& graph, const WriteOptions& options = {});
void write_part21(const Graph& graph, std::ostream& out, const WriteOptions& options = {});

// The value exactly as it appears in a file: format_real(5) == "5.", format_real(1e-5) == "1.E-05".
std::string format_real(double value);
std::string format_string(std::string_view utf8);  // with the quotes and the escapes
std::string format_value(const Value& value);

// ISO 8601 UTC time stamp ("2024-01-31T12:00:00") for FILE_NAME: from SOURCE_DATE_EPOCH when set
// and valid, else the current time.
std::string time_stamp_now();
std::string time_stamp_of(std::int64_t unix_seconds);

}  // namespace ncbridge::step_writer::part21
