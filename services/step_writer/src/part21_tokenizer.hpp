#pragma once
// Splits Part 21 text into tokens, one at a time, tracking line and column (internal).
#include <cstdint>
#include <string>
#include <string_view>

#include "ncbridge/common/error.hpp"

namespace ncbridge::step_writer::part21 {

enum class TokenKind {
  Keyword,       // ENTITY_NAME, ISO-10303-21, HEADER, !USER_KEYWORD
  InstanceName,  // #12 (text without the #)
  Integer, Real,
  String,        // text between the quotes, still escaped
  Enumeration,   // text between the dots
  Binary,        // text between the double quotes
  Dollar, Star, LeftParen, RightParen, Comma, Semicolon, Equals,
  End,           // end of text
};

struct Token {
  TokenKind kind = TokenKind::End;
  std::string_view text;
  std::uint32_t line = 1, column = 1;          // where it starts
  std::uint32_t end_line = 1, end_column = 1;  // just after its last character
};

std::string_view describe(TokenKind kind);

class Tokenizer {
 public:
  Tokenizer(std::string_view text, const std::string& file_name) : text_(text), file_(file_name) {}

  // The next token; throws ncbridge::InputError on characters that start no token, unterminated
  // strings/comments/binaries.
  Token next();
  SourceLocation location(std::uint32_t line, std::uint32_t column) const { return {file_, line, column}; }
  [[noreturn]] void fail(std::uint32_t line, std::uint32_t column, const std::string& message) const;
  // Skips the body of a section this reader does not interpret, up to (not over) its ENDSEC.
  void skip_to_endsec();
  // Skips everything up to the end of the text (SIGNATURE sections after END-ISO-10303-21;).
  bool only_blanks_left();

 private:
  char peek(std::size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
  bool at_end(std::size_t ahead = 0) const { return pos_ + ahead >= text_.size(); }
  void advance();
  void skip_blanks_and_comments();
  Token finish(Token token, std::size_t start);

  std::string_view text_;
  const std::string& file_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 1, column_ = 1;
};

}  // namespace ncbridge::step_writer::part21
