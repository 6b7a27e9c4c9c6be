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
  bool decisive = false;  // a construct only this dialect writes decided (else RS274/NGC assumed)
};

// Looks at the first lines of the program text (at most 64 KiB).
DetectedDialect detect_dialect(std::string_view text);
// Throws InputError when the file cannot be read.
DetectedDialect detect_dialect_file(const std::filesystem::path& program);

// Detection that reads. The decisive constructs first; when none decides, the program is read in
// each candidate dialect (RS274/NGC, Fanuc, Mach3/4, SINUMERIK 840D, in that order of
// preference) and the first that reads it whole is taken. The reason says which readings read it
// whole and whether they move the tool alike (when they do, the choice changes nothing), and
// where the others stop. `options` (tools, subroutine path) are those of the real reading.
DetectedDialect detect_dialect_reading(const std::filesystem::path& program, const Options& options);
DetectedDialect detect_dialect_reading(std::string_view text, const std::string& name, const Options& options);

// "rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain", "auto".
std::string_view dialect_name(Dialect dialect);
// The inverse; false for an unknown name.
bool parse_dialect_name(std::string_view name, Dialect& dialect);

}  // namespace ncbridge::interpreter
