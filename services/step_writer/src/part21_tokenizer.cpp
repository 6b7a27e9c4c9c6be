#include "part21_tokenizer.hpp"

namespace ncbridge::step_writer::part21 {
namespace {

bool is_upper_or_underscore(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_keyword_char(char c) { return is_upper_or_underscore(c) || is_digit(c) || c == '-'; }
bool is_hex(char c) { return is_digit(c) || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f'); }

std::string printable(char c) {
  auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7F) return std::string("'") + c + "'";
  static const char hex[] = "0123456789ABCDEF";
  return std::string("byte 0x") + hex[u >> 4] + hex[u & 0xF];
}

}  // namespace

std::string_view describe(TokenKind kind) {
  switch (kind) {
    case TokenKind::Keyword: return "a keyword";
    case TokenKind::InstanceName: return "an instance name";
    case TokenKind::Integer: return "an integer";
    case TokenKind::Real: return "a real";
    case TokenKind::String: return "a string";
    case TokenKind::Enumeration: return "an enumeration";
    case TokenKind::Binary: return "a binary";
    case TokenKind::Dollar: return "'$'";
    case TokenKind::Star: return "'*'";
    case TokenKind::LeftParen: return "'('";
    case TokenKind::RightParen: return "')'";
    case TokenKind::Comma: return "','";
    case TokenKind::Semicolon: return "';'";
    case TokenKind::Equals: return "'='";
    case TokenKind::End: return "the end of the file";
  }
  return "a token";
}

void Tokenizer::fail(std::uint32_t line, std::uint32_t column, const std::string& message) const {
  throw InputError(location(line, column), message);
}

void Tokenizer::advance() {
  if (text_[pos_] == '\n') {
    ++line_;
    column_ = 1;
  } else {
    ++column_;
  }
  ++pos_;
}

void Tokenizer::skip_blanks_and_comments() {
  for (;;) {
    while (!at_end() && static_cast<unsigned char>(peek()) <= 0x20) advance();
    if (peek() == '/' && peek(1) == '*') {
      std::uint32_t line = line_, column = column_;
      advance();
      advance();
      while (!at_end() && !(peek() == '*' && peek(1) == '/')) advance();
      if (at_end()) fail(line, column, "comment is never closed with */");
      advance();
      advance();
      continue;
    }
    return;
  }
}

void Tokenizer::skip_to_endsec() {
  for (;;) {
    skip_blanks_and_comments();
    if (at_end()) return;
    if (text_.substr(pos_, 6) == "ENDSEC" && !is_keyword_char(peek(6))) return;
    if (peek() == '\'') {
      std::uint32_t line = line_, column = column_;
      advance();
      while (!at_end() && peek() != '\'') advance();
      if (at_end()) fail(line, column, "string is never closed with '");
    }
    advance();
  }
}

bool Tokenizer::only_blanks_left() {
  skip_blanks_and_comments();
  return at_end();
}

Token Tokenizer::finish(Token token, std::size_t start) {
  token.text = text_.substr(start, pos_ - start);
  token.end_line = line_;
  token.end_column = column_;
  return token;
}

Token Tokenizer::next() {
  skip_blanks_and_comments();
  Token token;
  token.line = line_;
  token.column = column_;
  if (at_end()) return finish(token, pos_);

  char c = peek();
  auto single = [&](TokenKind kind) {
    token.kind = kind;
    std::size_t start = pos_;
    advance();
    return finish(token, start);
  };
  switch (c) {
    case '$': return single(TokenKind::Dollar);
    case '*': return single(TokenKind::Star);
    case '(': return single(TokenKind::LeftParen);
    case ')': return single(TokenKind::RightParen);
    case ',': return single(TokenKind::Comma);
    case ';': return single(TokenKind::Semicolon);
    case '=': return single(TokenKind::Equals);
    default: break;
  }

  if (c == '#') {
    advance();
    std::size_t start = pos_;
    if (!is_digit(peek())) fail(token.line, token.column, "'#' must be followed by the instance number");
    while (is_digit(peek())) advance();
    token.kind = TokenKind::InstanceName;
    Token t = finish(token, start);
    return t;
  }

  if (c == '\'') {
    advance();
    std::size_t start = pos_;
    for (;;) {
      if (at_end()) fail(token.line, token.column, "string is never closed with '");
      if (peek() == '\'') {
        if (peek(1) == '\'') {
          advance();
          advance();
          continue;
        }
        break;
      }
      advance();
    }
    token.kind = TokenKind::String;
    Token t = finish(token, start);
    advance();  // closing quote
    t.end_line = line_;
    t.end_column = column_;
    return t;
  }

  if (c == '"') {
    advance();
    std::size_t start = pos_;
    while (!at_end() && peek() != '"') {
      if (!is_hex(peek())) fail(line_, column_, "binary value may only hold hexadecimal digits, found " + printable(peek()));
      advance();
    }
    if (at_end()) fail(token.line, token.column, "binary value is never closed with \"");
    token.kind = TokenKind::Binary;
    Token t = finish(token, start);
    advance();
    t.end_line = line_;
    t.end_column = column_;
    return t;
  }

  if (c == '.' && is_upper_or_underscore(peek(1))) {
    advance();
    std::size_t start = pos_;
    while (is_upper_or_underscore(peek()) || is_digit(peek())) advance();
    if (peek() != '.') fail(token.line, token.column, "enumeration value must end with '.'");
    token.kind = TokenKind::Enumeration;
    Token t = finish(token, start);
    advance();
    t.end_line = line_;
    t.end_column = column_;
    return t;
  }

  if (is_digit(c) || ((c == '-' || c == '+') && (is_digit(peek(1)) || peek(1) == '.')) ||
      (c == '.' && is_digit(peek(1)))) {
    std::size_t start = pos_;
    token.kind = TokenKind::Integer;
    if (c == '-' || c == '+') advance();
    while (is_digit(peek())) advance();
    if (peek() == '.') {
      token.kind = TokenKind::Real;
      advance();
      while (is_digit(peek())) advance();
      if (peek() == 'E' || peek() == 'e') {
        std::size_t k = 1;
        if (peek(1) == '+' || peek(1) == '-') k = 2;
        if (!is_digit(peek(k))) fail(line_, column_, "real has an exponent without digits");
        for (std::size_t j = 0; j < k; ++j) advance();
        while (is_digit(peek())) advance();
      }
    }
    return finish(token, start);
  }

  if (is_upper_or_underscore(c) || c == '!') {
    std::size_t start = pos_;
    advance();
    while (is_keyword_char(peek())) advance();
    token.kind = TokenKind::Keyword;
    return finish(token, start);
  }

  fail(token.line, token.column, "unexpected " + printable(c));
}

}  // namespace ncbridge::step_writer::part21
