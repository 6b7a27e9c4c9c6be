#include "number_format.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace ncbridge::gcode_writer {

namespace {

constexpr double kPowers[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
constexpr double kLargest = 9.0e15;  // integers below this are exact in a double

int clamp_decimals(int d) { return d < 0 ? 0 : d > 9 ? 9 : d; }

}  // namespace

double rounded(double value, int decimals) {
  if (value == 0) return 0.0;
  const double p = kPowers[clamp_decimals(decimals)];
  const double scaled = value * p;
  if (!(std::fabs(scaled) < kLargest)) return value;
  const double r = static_cast<double>(static_cast<long long>(scaled + (scaled < 0 ? -0.5 : 0.5))) / p;
  return r == 0 ? 0.0 : r;  // no -0
}

void append_number(std::string& out, double value, const NumberStyle& style) {
  if (value == 0) {
    if (style.plus_sign) out.push_back('+');
    out.push_back('0');
    if (style.point_always) out.push_back('.');
    return;
  }
  const int d = clamp_decimals(style.decimals);
  const double scaled = value * kPowers[d];
  if (!(std::fabs(scaled) < kLargest)) {
    // far beyond any machine's travel: still fixed point, never an exponent
    char buffer[400];
    std::snprintf(buffer, sizeof buffer, "%.*f", d, std::isfinite(value) ? value : 0.0);
    if (style.plus_sign && value >= 0) out.push_back('+');
    out += buffer;
    return;
  }
  long long n = static_cast<long long>(scaled + (scaled < 0 ? -0.5 : 0.5));
  const bool negative = n < 0;
  if (negative) n = -n;
  unsigned long long unit = 1;
  for (int i = 0; i < d; ++i) unit *= 10;
  unsigned long long whole = static_cast<unsigned long long>(n) / unit;
  unsigned long long fraction = static_cast<unsigned long long>(n) % unit;
  if (negative && n != 0) {
    out.push_back('-');
  } else if (style.plus_sign) {
    out.push_back('+');
  }
  char digits[32];
  int len = 0;
  do {
    digits[len++] = static_cast<char>('0' + whole % 10);
    whole /= 10;
  } while (whole != 0);
  while (len > 0) out.push_back(digits[--len]);
  if (fraction == 0) {
    if (style.point_always) out.push_back('.');
    return;
  }
  int width = d;
  while (fraction % 10 == 0) {
    fraction /= 10;
    --width;
  }
  out.push_back('.');
  char frac[16];
  for (int i = width - 1; i >= 0; --i) {
    frac[i] = static_cast<char>('0' + fraction % 10);
    fraction /= 10;
  }
  out.append(frac, static_cast<std::size_t>(width));
}

std::string format_number(double value, const NumberStyle& style) {
  std::string s;
  append_number(s, value, style);
  return s;
}

}  // namespace ncbridge::gcode_writer
