#pragma once
// The controller dialects the gcode_writer writes: the five the interpreter reads.
#include <optional>
#include <string_view>

namespace ncbridge::gcode_writer {

enum class Dialect { Rs274Ngc, Fanuc, Mach3, Siemens840D, Heidenhain };

// "rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain" (the names `--dialect` takes).
std::string_view dialect_name(Dialect dialect);
std::optional<Dialect> parse_dialect(std::string_view name);
// The file extension a program of the dialect usually has: .ngc .nc .tap .mpf .h
std::string_view program_extension(Dialect dialect);

}  // namespace ncbridge::gcode_writer
