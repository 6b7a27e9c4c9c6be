#include "ncbridge/gcode_writer/dialect.hpp"

#include "dialect_writer.hpp"

namespace ncbridge::gcode_writer {

std::string_view dialect_name(Dialect dialect) {
  switch (dialect) {
    case Dialect::Rs274Ngc: return "rs274ngc";
    case Dialect::Fanuc: return "fanuc";
    case Dialect::Mach3: return "mach3";
    case Dialect::Siemens840D: return "siemens840d";
    case Dialect::Heidenhain: return "heidenhain";
  }
  return "rs274ngc";
}

std::optional<Dialect> parse_dialect(std::string_view name) {
  for (Dialect d : {Dialect::Rs274Ngc, Dialect::Fanuc, Dialect::Mach3, Dialect::Siemens840D, Dialect::Heidenhain}) {
    if (dialect_name(d) == name) return d;
  }
  return std::nullopt;
}

std::string_view program_extension(Dialect dialect) {
  switch (dialect) {
    case Dialect::Rs274Ngc: return ".ngc";
    case Dialect::Fanuc: return ".nc";
    case Dialect::Mach3: return ".tap";
    case Dialect::Siemens840D: return ".mpf";
    case Dialect::Heidenhain: return ".h";
  }
  return ".ngc";
}

void DialectWriter::refuse(const std::string& construct, const std::string& why) const {
  std::string message = std::string(dialect_name(options_.dialect)) + " cannot express " + construct;
  if (!why.empty()) message += ": " + why;
  throw InputError({where_.file, where_.line, 0}, message);
}

int DialectWriter::length_decimals() const {
  const int mm = options_.decimals.value_or(4);
  return reader_.units == canonical::Units::Inches ? mm + 1 : mm;
}

}  // namespace ncbridge::gcode_writer
