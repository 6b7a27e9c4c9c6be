#pragma once
// Numbers as controllers read them: fixed point, never an exponent, trailing zeros dropped.
// What a written number reads back as is `rounded` of the value: the writer keeps its model
// of the reader on those values, so that what it computes from them (arc centre offsets,
// incremental moves) adds up exactly on the reader's side.
#include <string>

namespace ncbridge::gcode_writer {

struct NumberStyle {
  int decimals = 4;           // digits after the point at most
  bool point_always = false;  // "10." for 10 (Fanuc: a number without a point counts increments)
  bool plus_sign = false;     // "+10" (Heidenhain)
};

// The value a number written with `decimals` digits reads back as.
double rounded(double value, int decimals);
void append_number(std::string& out, double value, const NumberStyle& style);
std::string format_number(double value, const NumberStyle& style);

}  // namespace ncbridge::gcode_writer
