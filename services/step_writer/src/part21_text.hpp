#pragma once
// Appending Part 21 tokens to a text buffer, shared by the generic writer (part21_writer.cpp)
// and the streaming ISO 14649 writer (cc1_writer.cpp). Defined in part21_writer.cpp.
#include <string>
#include <string_view>

namespace ncbridge::step_writer::part21 {

// Longest text write_real produces (sign, 17 digits, point, exponent), with room to spare.
inline constexpr std::size_t kMaxRealChars = 32;

// Writes `value` as a Part 21 real, shortest round-trip (5. -0.5 1.E-05), at `first`; returns the
// end. Throws std::invalid_argument for NaN and infinities.
char* write_real(char* first, double value);

void append_real(std::string& out, double value);
void append_string(std::string& out, std::string_view utf8);  // with the quotes and the escapes

}  // namespace ncbridge::step_writer::part21
