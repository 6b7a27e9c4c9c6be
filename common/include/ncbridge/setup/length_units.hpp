#pragma once
// The length units a setup file (tool table, stock) is written in; values are kept in mm.
#include <cstdint>

namespace ncbridge::setup {

enum class LengthUnits : std::uint8_t { Millimeters, Inches };

}  // namespace ncbridge::setup
