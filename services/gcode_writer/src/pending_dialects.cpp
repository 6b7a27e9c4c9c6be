// SINUMERIK 840D and Heidenhain writers: not written yet (step 2 of issue 11).
#include "dialect_writer.hpp"

namespace ncbridge::gcode_writer {

std::unique_ptr<DialectWriter> make_siemens840d_writer(const Options&, TextOutput&, const WriterLocation& where) {
  throw InputError({where.file, 0, 0}, "siemens840d: the writer for this dialect is not built yet");
}

std::unique_ptr<DialectWriter> make_heidenhain_writer(const Options&, TextOutput&, const WriterLocation& where) {
  throw InputError({where.file, 0, 0}, "heidenhain: the writer for this dialect is not built yet");
}

}  // namespace ncbridge::gcode_writer
