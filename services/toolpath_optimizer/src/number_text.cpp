#include "ncbridge/toolpath_optimizer/number_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace ncbridge::toolpath_optimizer {

void append_number(std::string& out, double value, int decimals) {
  // The largest double in fixed notation has 309 integer digits; decimals are capped so that
  // every finite value fits the buffer.
  decimals = std::clamp(decimals, 0, 17);
  char buffer[400];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  if (result.ec != std::errc()) throw std::logic_error("append_number: a number does not fit its buffer");
  char* end = result.ptr;
  if (decimals > 0) {
    while (end[-1] == '0') --end;
    if (end[-1] == '.') --end;
  }
  std::string_view text(buffer, static_cast<std::size_t>(end - buffer));
  if (text == "-0") text = "0";
  out.append(text);
}

}  // namespace ncbridge::toolpath_optimizer
