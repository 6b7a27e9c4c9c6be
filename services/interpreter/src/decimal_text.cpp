#include "decimal_text.hpp"

#include <charconv>
#include <cmath>

namespace ncbridge::interpreter {

namespace {

constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr std::uint64_t kExactMantissa = std::uint64_t{1} << 53;

constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

void append_fixed_slow(std::string& out, double value, int precision) {
  char tmp[400];
  auto r = std::to_chars(tmp, tmp + sizeof tmp, value, std::chars_format::fixed, precision);
  out.append(tmp, r.ptr);
}

}  // namespace

bool DecimalDigits::exact_value(bool negative, double& out) const {
  // Clinger's fast path: an exact mantissa divided by an exact power of ten rounds correctly.
  if (inexact_ || mantissa_ > kExactMantissa || decimals_ > 22) return false;
  const double v = static_cast<double>(mantissa_) / kPow10[decimals_];
  out = negative ? -v : v;
  return true;
}

bool parse_decimal(const char* first, const char* last, double& out) {
  const char* p = first;
  const bool negative = p != last && *p == '-';
  if (negative) ++p;
  DecimalDigits digits;
  bool point = false, any = false;
  for (; p != last; ++p) {
    const char c = *p;
    if (c == '.') {
      if (point) return false;
      point = true;
    } else if (c >= '0' && c <= '9') {
      any = true;
      digits.digit(c, point);
    } else {
      return false;
    }
  }
  if (!any) return false;
  if (digits.exact_value(negative, out)) return true;
  auto r = std::from_chars(first, last, out);
  return r.ec == std::errc() && r.ptr == last;
}

void append_fixed(std::string& out, double value, int precision) {
  // Exact path for precision 4 and |value| < 1e9: value * 1e4 is within one unit in the last
  // place of the exact product, so unless the scaled fraction is that close to one half,
  // rounding it gives the digits printf gives (it rounds the exact binary value half to even).
  if (value == 0.0 && precision == 4) {  // a, b, c of most moves
    out.append(std::signbit(value) ? "-0.0000" : "0.0000");
    return;
  }
  const double magnitude = std::fabs(value);
  if (precision != 4 || !(magnitude < 1e9)) {
    append_fixed_slow(out, value, precision);
    return;
  }
  const double scaled = magnitude * 1e4;
  const auto whole = static_cast<std::uint64_t>(scaled);
  const double fraction = scaled - static_cast<double>(whole);
  if (std::fabs(fraction - 0.5) <= scaled * 4.5e-16 + 1e-300) {
    append_fixed_slow(out, value, precision);
    return;
  }
  const std::uint64_t units = whole + (fraction > 0.5 ? 1 : 0);
  char tmp[24];
  char* const end = tmp + sizeof tmp;
  char* p = end;
  const auto decimals = static_cast<unsigned>(units % 10000);
  p -= 2;
  p[0] = kPairs[2 * (decimals % 100)];
  p[1] = kPairs[2 * (decimals % 100) + 1];
  p -= 2;
  p[0] = kPairs[2 * (decimals / 100)];
  p[1] = kPairs[2 * (decimals / 100) + 1];
  *--p = '.';
  std::uint64_t integer = units / 10000;
  while (integer >= 100) {
    const auto pair = static_cast<unsigned>(integer % 100);
    integer /= 100;
    p -= 2;
    p[0] = kPairs[2 * pair];
    p[1] = kPairs[2 * pair + 1];
  }
  if (integer >= 10) {
    p -= 2;
    p[0] = kPairs[2 * integer];
    p[1] = kPairs[2 * integer + 1];
  } else {
    *--p = static_cast<char>('0' + integer);
  }
  if (std::signbit(value)) *--p = '-';
  out.append(p, end);
}

}  // namespace ncbridge::interpreter
