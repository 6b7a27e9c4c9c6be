#pragma once
// A problem found in a Part 21 file that does not stop reading: a warning of the reader, or an
// error/warning of the schema check, with the instance and attribute it is about.
#include <string>
#include <vector>

#include "ncbridge/common/error.hpp"
#include "ncbridge/step_writer/part21_value.hpp"

namespace ncbridge::step_writer {

enum class Severity { Error, Warning };

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLocation where;            // file and line of the instance (line 0 for built graphs)
  part21::InstanceId instance = 0; // 0 when not about one instance
  std::string entity;              // upper case entity name, when about an instance
  std::string attribute;           // attribute name from the schema, when about one attribute
  std::string message;

  // "file:line: error: #10 MACHINING_WORKINGSTEP.its_feature: message"
  std::string to_string() const;
};

std::size_t count_errors(const std::vector<Diagnostic>& diagnostics);

}  // namespace ncbridge::step_writer
