// libFuzzer target: 3D-printer G-code through the toolpath optimizer's printer front-end, the
// optimizer and the printer writer; what is written is read back. The first byte picks the
// flavour and whether G0 runs may become arcs. Input must be read or refused with an InputError, never crash; the written output
// must read back without an error.
#include <cstdint>
#include <string>
#include <string_view>

#include "ncbridge/common/error.hpp"
#include "ncbridge/toolpath_optimizer/optimizer.hpp"
#include "ncbridge/toolpath_optimizer/printer_reader.hpp"
#include "ncbridge/toolpath_optimizer/printer_writer.hpp"

namespace opt = ncbridge::toolpath_optimizer;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto flavor = static_cast<opt::PrinterFlavor>(data[0] % 3);
  const std::string_view input(reinterpret_cast<const char*>(data) + 1, size - 1);
  std::string written;
  try {
    opt::PrinterWriter writer([&](std::string_view chunk) { written.append(chunk); });
    opt::OptimizerOptions options;
    options.traverse_arcs = (data[0] / 3) % 2 == 1;
    opt::Optimizer optimizer(options, writer);
    opt::PrinterReader reader("fuzz.gcode", flavor, optimizer);
    reader.text(input);
    reader.finish();
  } catch (const ncbridge::InputError&) {
    return 0;
  }
  opt::ElementCollector back;
  opt::PrinterReader again("written.gcode", flavor, back);
  again.text(written);  // an InputError here is a writer bug: libFuzzer reports the exception
  again.finish();
  return 0;
}
