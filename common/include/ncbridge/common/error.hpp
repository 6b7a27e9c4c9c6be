#pragma once
// Errors with the place in the user's input they are about (file, line, column).
// Every stage reports bad input by throwing ncbridge::InputError; the edges (CLI, services)
// catch it, print `file:line:column: error: message`, and exit non-zero / publish a status.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace ncbridge {

struct SourceLocation {
  std::string file;      // as the user named it; empty when the input has no file (a DDS payload)
  std::uint32_t line = 0;    // 1-based; 0 = unknown
  std::uint32_t column = 0;  // 1-based; 0 = unknown

  std::string to_string() const;  // "file:line:column", omitting unknown parts
};

class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, std::string message);
  const SourceLocation& where() const noexcept { return where_; }
  const std::string& message() const noexcept { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

}  // namespace ncbridge
