// libFuzzer target: tool data. The same bytes as the project's tool list (or, by content, a
// Fusion 360 library or a FreeCAD bit), a FreeCAD bit, and a LinuxCNC tool table in inches: each
// must be read or refused with an InputError, never crash.
#include <cstdint>
#include <string>
#include <string_view>

#include "ncbridge/common/error.hpp"
#include "ncbridge/setup/freecad_tools.hpp"
#include "ncbridge/setup/fusion_tools.hpp"
#include "ncbridge/setup/tool_list.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  using namespace ncbridge::setup;
  try {
    (void)parse_tool_list(input, "fuzz.json");
  } catch (const ncbridge::InputError&) {
  }
  try {
    (void)parse_freecad_tool_bit(input, "fuzz.fctb", 1);
  } catch (const ncbridge::InputError&) {
  }
  try {
    (void)parse_fusion_tool_library(input, "fuzz.json");
  } catch (const ncbridge::InputError&) {
  }
  try {
    (void)parse_linuxcnc_tool_table(input, LengthUnits::Inches, "fuzz.tbl");
  } catch (const ncbridge::InputError&) {
  }
  return 0;
}
