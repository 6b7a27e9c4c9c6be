#pragma once
// `--dialect auto`: which controller dialect a program is written in, from its syntax alone
// (Heidenhain `BEGIN PGM`/`L X+..`, Siemens `;` comments, `R1=`, `CYCLE8x(`, `T="name"`,
// Fanuc O numbers and macro B, Mach's post header, RS274/NGC o-words and `#<name>`).
#include <filesystem>
#include <string>
#include <string_view>

#include "ncbridge/interpreter/interpreter.hpp"

namespace ncbridge::interpreter {

struct DetectedDialect {
  Dialect dialect = Dialect::Rs274Ngc;
  std::string reason;  // the evidence, for the message "dialect: fanuc (O-number line 3)"
};

// Looks at the first lines of the program text (at most 64 KiB).
DetectedDialect detect_dialect(std::string_view text);
// Throws InputError when the file cannot be read.
DetectedDialect detect_dialect_file(const std::filesystem::path& program);

// "rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain", "auto".
std::string_view dialect_name(Dialect dialect);
// The inverse; false for an unknown name.
bool parse_dialect_name(std::string_view name, Dialect& dialect);

}  // namespace ncbridge::interpreter
