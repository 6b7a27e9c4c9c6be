// Mach3/Mach4: the Fanuc writer with Mach's conventions (values as written, G4 P and cycle P in
// seconds, no O number, no G74), as services/interpreter/src/mach3/ reads them.
#include "fanuc_writer.hpp"

namespace ncbridge::gcode_writer {

std::unique_ptr<DialectWriter> make_mach3_writer(const Options& o, TextOutput& out, const WriterLocation& where) {
  return std::make_unique<FanucWriter>(o, out, where, true);
}

}  // namespace ncbridge::gcode_writer
