#include "express_lexer.hpp"

namespace ncbridge::step_writer::express {
namespace {

bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

void Lexer::fail(const Token& at, const std::string& message) const {
  throw InputError(SourceLocation{file_, at.line, at.column}, message);
}

void Lexer::advance() {
  if (text_[pos_] == '\n') {
    ++line_;
    column_ = 1;
  } else {
    ++column_;
  }
  ++pos_;
}

void Lexer::skip_blanks_and_remarks() {
  for (;;) {
    while (pos_ < text_.size() && static_cast<unsigned char>(peek()) <= 0x20) advance();
    if (peek() == '(' && peek(1) == '*') {
      Token start{TokenKind::End, {}, line_, column_};
      int depth = 0;
      do {
        if (pos_ >= text_.size()) fail(start, "remark is never closed with *)");
        if (peek() == '(' && peek(1) == '*') {
          ++depth;
          advance();
        } else if (peek() == '*' && peek(1) == ')') {
          --depth;
          advance();
        }
        advance();
      } while (depth > 0);
      continue;
    }
    if (peek() == '-' && peek(1) == '-') {
      while (pos_ < text_.size() && peek() != '\n') advance();
      continue;
    }
    return;
  }
}

Token Lexer::next() {
  skip_blanks_and_remarks();
  Token token{TokenKind::End, {}, line_, column_};
  std::size_t start = pos_;
  if (pos_ >= text_.size()) return token;
  char c = peek();
  if (is_letter(c) || c == '_') {
    while (is_letter(peek()) || is_digit(peek()) || peek() == '_') advance();
    token.kind = TokenKind::Identifier;
  } else if (is_digit(c)) {
    while (is_digit(peek()) || peek() == '.' || peek() == 'e' || peek() == 'E') advance();
    token.kind = TokenKind::Number;
  } else if (c == '\'') {
    advance();
    for (;;) {
      if (pos_ >= text_.size()) fail(token, "string is never closed with '");
      if (peek() == '\'' && peek(1) == '\'') {
        advance();
        advance();
        continue;
      }
      if (peek() == '\'') break;
      advance();
    }
    advance();
    token.kind = TokenKind::String;
  } else if (c == '"') {
    advance();
    while (pos_ < text_.size() && peek() != '"') advance();
    if (pos_ >= text_.size()) fail(token, "encoded string is never closed with \"");
    advance();
    token.kind = TokenKind::String;
  } else {
    // Two-character symbols first; everything else is one character.
    static constexpr std::string_view pairs[] = {":=", "<=", ">=", "<>", "||", "**", "<*", ":<>:", ":=:"};
    token.kind = TokenKind::Symbol;
    std::string_view rest = text_.substr(pos_);
    std::size_t length = 1;
    for (auto p : pairs)
      if (rest.substr(0, p.size()) == p && p.size() > length) length = p.size();
    for (std::size_t k = 0; k < length; ++k) advance();
  }
  token.text = text_.substr(start, pos_ - start);
  return token;
}

}  // namespace ncbridge::step_writer::express
