#include "ncbridge/step_writer/diagnostic.hpp"

namespace ncbridge::step_writer {

std::string Diagnostic::to_string() const {
  SourceLocation at = where;
  at.column = 0;  // instance-level problems: the line is what a user looks for
  std::string s = at.to_string();
  s += severity == Severity::Error ? ": error: " : ": warning: ";
  if (instance != 0) {
    s += '#' + std::to_string(instance);
    if (!entity.empty()) s += ' ' + entity;
    if (!attribute.empty()) s += '.' + attribute;
    s += ": ";
  }
  s += message;
  return s;
}

std::size_t count_errors(const std::vector<Diagnostic>& diagnostics) {
  std::size_t n = 0;
  for (const auto& d : diagnostics) n += d.severity == Severity::Error;
  return n;
}

}  // namespace ncbridge::step_writer
