#pragma once
// Decimal numbers in and out, fast and exact: reading the program's numbers, and printing
// reals as printf("%.4f") does (rs274's listing format). Both take a short exact path for the
// common case and fall back to the standard library where that path cannot be sure.
#include <cstdint>
#include <string>

namespace ncbridge::interpreter {

// The digits of a decimal number as they are read, one at a time (the reader skips blanks
// between them): up to 19 significant digits are kept exactly.
class DecimalDigits {
 public:
  void digit(char c, bool after_point) {
    if (mantissa_ == 0 && c == '0') {
      if (after_point) ++decimals_;
      return;
    }
    if (++significant_ > 19) {
      inexact_ = true;
      return;
    }
    mantissa_ = mantissa_ * 10 + static_cast<std::uint64_t>(c - '0');
    if (after_point) ++decimals_;
  }
  // The value, correctly rounded, when the fast path is exact; false otherwise.
  bool exact_value(bool negative, double& out) const;

 private:
  std::uint64_t mantissa_ = 0;
  int significant_ = 0, decimals_ = 0;
  bool inexact_ = false;
};

// Reads `[-]digits[.digits]` (no exponent, no spaces) from [first, last) into `out`, correctly
// rounded. False when the text is not such a number.
bool parse_decimal(const char* first, const char* last, double& out);

// Appends `value` with `precision` decimals, exactly as printf("%.*f") prints it.
void append_fixed(std::string& out, double value, int precision);

}  // namespace ncbridge::interpreter
