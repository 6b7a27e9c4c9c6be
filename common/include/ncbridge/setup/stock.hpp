#pragma once
// The raw piece (stock) a program cuts, in the program frame: docs/formats/stock.md.
#include <array>
#include <filesystem>
#include <string>
#include <string_view>

#include "ncbridge/setup/length_units.hpp"

namespace ncbridge::setup {

struct Stock {
  // An axis-aligned block in the program frame (the active work offset), millimetres.
  std::array<double, 3> min{0, 0, 0};
  std::array<double, 3> max{0, 0, 0};
  // The units the file gave ("units", mm when it says none); min and max are mm whatever they are.
  LengthUnits file_units = LengthUnits::Millimeters;

  double size(int axis) const { return max[axis] - min[axis]; }
};

// `{"units":"mm","shape":"block","min":[x,y,z],"max":[x,y,z]}`, JSON or YAML; "units" may be
// "mm" or "inch" (converted to mm). Unknown fields are ignored; errors throw InputError.
Stock read_stock(const std::filesystem::path& file);
Stock parse_stock(std::string_view text, const std::string& file_name_for_errors);

}  // namespace ncbridge::setup
