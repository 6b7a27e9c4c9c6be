#pragma once
// Splits EXPRESS (ISO 10303-11) text into tokens: identifiers/keywords, numbers, strings and
// symbols, skipping (* nested remarks *) and -- tail remarks (internal).
#include <cstdint>
#include <string>
#include <string_view>

#include "ncbridge/common/error.hpp"

namespace ncbridge::step_writer::express {

enum class TokenKind { Identifier, Number, String, Symbol, End };

struct Token {
  TokenKind kind = TokenKind::End;
  std::string_view text;  // identifiers as written (compare with upper())
  std::uint32_t line = 1, column = 1;
};

class Lexer {
 public:
  Lexer(std::string_view text, const std::string& file_name) : text_(text), file_(file_name) {}
  Token next();
  [[noreturn]] void fail(const Token& at, const std::string& message) const;

 private:
  char peek(std::size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
  void advance();
  void skip_blanks_and_remarks();

  std::string_view text_;
  const std::string& file_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 1, column_ = 1;
};

}  // namespace ncbridge::step_writer::express
