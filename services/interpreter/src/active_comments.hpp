#pragma once
// LinuxCNC's active comments (convert_comment): (MSG,...), (DEBUG,...), (PRINT,...), (LOG,...),
// (LOGOPEN,...), (LOGAPPEND,...), (LOGCLOSE), (ABORT,...). The keyword is matched after leading
// blanks in any case; DEBUG, PRINT, LOG and ABORT texts have their parameters substituted.
#include <string>
#include <string_view>

#include "parameters.hpp"

namespace ncbridge::interpreter {

enum class ActiveComment { None, Debug, Print, Log, LogOpen, LogAppend, LogClose, Abort };

// Which active comment `text` (a plain comment's text) is, and the text after its keyword.
ActiveComment classify_comment(std::string_view text, std::string_view& rest);

// LinuxCNC's convert_param_comment: #n and #<name> become their values, printed with "%lf"
// until a %d ("%.0f"), %f ("%.4f") or %.Nf ("%.Nf") changes the format for the rest of the text;
// values within 0.0001 of zero print as 0; an unknown parameter prints ######. A # at the end or
// a #< without > stops the text there (rs274 shows what came before).
std::string expand_comment_parameters(std::string_view text, const Parameters& parameters);

}  // namespace ncbridge::interpreter
