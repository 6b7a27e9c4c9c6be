#include "lowering/infix_expression.hpp"

#include <charconv>

#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter::lowering {

char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }
bool is_alpha(char c) { c = upper(c); return c >= 'A' && c <= 'Z'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

bool read_decimal(std::string_view s, std::size_t& pos, double& value, bool* had_point) {
  std::size_t i = pos;
  char buf[64];
  std::size_t n = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) {
    if (s[i] == '-') buf[n++] = '-';
    ++i;
  }
  bool digit = false, point = false;
  while (i < s.size() && n < sizeof buf - 1) {
    if (is_digit(s[i])) {
      digit = true;
    } else if (s[i] == '.' && !point) {
      point = true;
    } else {
      break;
    }
    buf[n++] = s[i++];
  }
  if (!digit) return false;
  double v = 0;
  auto r = std::from_chars(buf, buf + n, v);
  if (r.ec != std::errc()) return false;
  value = v;
  pos = i;
  if (had_point) *had_point = point;
  return true;
}

InfixParser::InfixParser(std::string_view text, std::size_t pos, Block& block, const ExpressionSyntax& syntax,
                         const std::string& file, std::uint32_t line)
    : s_(text), pos_(pos), b_(block), syntax_(syntax), file_(file), line_(line) {}

void InfixParser::fail(std::size_t at, const std::string& message) const {
  throw InputError({file_, line_, static_cast<std::uint32_t>(at + 1)}, message);
}

ExprRef InfixParser::number(Block& block, double value, std::uint32_t column) {
  ExprNode node;
  node.op = ExprOp::Number;
  node.value = value;
  node.column = column;
  block.nodes.push_back(node);
  return static_cast<ExprRef>(block.nodes.size() - 1);
}

void InfixParser::skip_space() {
  while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t')) ++pos_;
}

ExprRef InfixParser::add(ExprOp op, std::size_t at, ExprRef a, ExprRef b) {
  ExprNode node;
  node.op = op;
  node.a = a;
  node.b = b;
  node.column = static_cast<std::uint32_t>(at + 1);
  b_.nodes.push_back(node);
  return static_cast<ExprRef>(b_.nodes.size() - 1);
}

ExprRef InfixParser::expression() {
  if (++depth_ > 64) fail(pos_, "Expression too deeply nested");
  ExprRef r = binary(0);
  --depth_;
  return r;
}

namespace {
bool word_at(std::string_view s, std::size_t pos, std::string_view word) {
  if (pos + word.size() > s.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i) {
    if (upper(s[pos + i]) != word[i]) return false;
  }
  // a keyword operator must not run into a following letter (EQ vs EQUAL)
  std::size_t end = pos + word.size();
  return end >= s.size() || !is_alpha(s[end]);
}
}  // namespace

// Levels: 0 OR/XOR, 1 AND, 2 comparisons, 3 + -, 4 * / MOD DIV.
bool InfixParser::operator_at(int level, ExprOp& op) {
  skip_space();
  if (pos_ >= s_.size()) return false;
  char c = s_[pos_];
  auto take = [&](std::size_t n, ExprOp o) { pos_ += n; op = o; return true; };
  switch (level) {
    case 0:
      if (word_at(s_, pos_, "OR")) return take(2, ExprOp::Or);
      if (word_at(s_, pos_, "XOR")) return take(3, ExprOp::Xor);
      return false;
    case 1:
      if (word_at(s_, pos_, "AND")) return take(3, ExprOp::And);
      return false;
    case 2:
      if (syntax_.word_comparisons) {
        static constexpr std::pair<std::string_view, ExprOp> kWords[] = {
            {"EQ", ExprOp::Eq}, {"NE", ExprOp::Ne}, {"GT", ExprOp::Gt},
            {"GE", ExprOp::Ge}, {"LT", ExprOp::Lt}, {"LE", ExprOp::Le}};
        for (const auto& [w, o] : kWords) {
          if (word_at(s_, pos_, w)) return take(2, o);
        }
      }
      if (syntax_.symbol_comparisons) {
        std::string_view rest = s_.substr(pos_);
        if (rest.starts_with("==")) return take(2, ExprOp::Eq);
        if (rest.starts_with("<>")) return take(2, ExprOp::Ne);
        if (rest.starts_with(">=")) return take(2, ExprOp::Ge);
        if (rest.starts_with("<=")) return take(2, ExprOp::Le);
        if (c == '>') return take(1, ExprOp::Gt);
        if (c == '<') return take(1, ExprOp::Lt);
      }
      return false;
    case 3:
      if (c == '+') return take(1, ExprOp::Plus);
      if (c == '-') return take(1, ExprOp::Minus);
      return false;
    case 4:
      if (c == '*') return take(1, ExprOp::Times);
      if (c == '/') return take(1, ExprOp::Divide);
      if (word_at(s_, pos_, "MOD")) return take(3, ExprOp::Modulo);
      if (word_at(s_, pos_, "DIV")) {
        pos_ += 3;
        op = ExprOp::Fix;  // marker: integer division, built by binary()
        return true;
      }
      return false;
    default:
      return false;
  }
}

ExprRef InfixParser::binary(int level) {
  if (level > 4) return primary();
  ExprRef left = binary(level + 1);
  for (;;) {
    std::size_t at = (skip_space(), pos_);
    ExprOp op;
    if (!operator_at(level, op)) return left;
    ExprRef right = binary(level + 1);
    if (op == ExprOp::Fix) {  // a DIV b = FIX(a / b) for the positive values programs use
      left = add(ExprOp::Fix, at, add(ExprOp::Divide, at, left, right));
    } else {
      left = add(op, at, left, right);
    }
  }
}

ExprRef InfixParser::primary() {
  skip_space();
  if (pos_ >= s_.size()) fail(pos_, "Missing value at end of line");
  if (++depth_ > 64) fail(pos_, "Expression too deeply nested");
  std::size_t start = pos_;
  char c = s_[pos_];
  ExprRef result = kNoExpr;
  if (c == syntax_.open) {
    ++pos_;
    result = expression();
    skip_space();
    if (pos_ >= s_.size() || s_[pos_] != syntax_.close) fail(start, std::string("Unclosed '") + syntax_.open + "': missing '" + syntax_.close + "'");
    ++pos_;
  } else if (c == '-' || c == '+') {
    ++pos_;
    ExprRef operand = primary();
    result = c == '-' ? add(ExprOp::Negate, start, operand) : operand;
  } else if (is_digit(c) || c == '.') {
    double v = 0;
    if (!read_decimal(s_, pos_, v)) fail(start, "Bad number format");
    result = number(b_, v, static_cast<std::uint32_t>(start + 1));
  } else {
    if (syntax_.variable) {
      std::size_t p = pos_;
      ExprRef v = syntax_.variable(s_, p, b_);
      if (v != kNoExpr) {
        pos_ = p;
        --depth_;
        return v;
      }
    }
    if (!is_alpha(c)) fail(start, std::string("Bad character '") + c + "' where a value was expected");
    std::string name;
    while (pos_ < s_.size() && (is_alpha(s_[pos_]) || is_digit(s_[pos_]))) name.push_back(upper(s_[pos_++]));
    skip_space();
    if (name == "NOT") {
      result = add(ExprOp::Not, start, primary());
    } else {
      if (pos_ >= s_.size() || s_[pos_] != syntax_.open) fail(start, "Unknown word '" + name + "' in expression");
      ++pos_;
      ExprRef a = expression();
      ExprRef b2 = kNoExpr;
      skip_space();
      if (pos_ < s_.size() && s_[pos_] == ',') {
        ++pos_;
        b2 = expression();
        skip_space();
      }
      if (pos_ >= s_.size() || s_[pos_] != syntax_.close) fail(start, "Missing '" + std::string(1, syntax_.close) + "' after the argument of " + name);
      ++pos_;
      // Fanuc ATAN[a]/[b]: the second argument follows a slash
      if ((name == "ATAN" || name == "ATN") && b2 == kNoExpr) {
        skip_space();
        if (pos_ < s_.size() && s_[pos_] == '/' && pos_ + 1 < s_.size() && s_[pos_ + 1] == syntax_.open) {
          ++pos_;
          b2 = primary();
        }
      }
      static constexpr std::pair<std::string_view, ExprOp> kUnary[] = {
          {"SIN", ExprOp::Sin},   {"COS", ExprOp::Cos},   {"TAN", ExprOp::Tan},   {"ASIN", ExprOp::Asin},
          {"ACOS", ExprOp::Acos}, {"SQRT", ExprOp::Sqrt}, {"SQR", ExprOp::Sqrt},  {"ABS", ExprOp::Abs},
          {"ROUND", ExprOp::Round}, {"FIX", ExprOp::Fix}, {"FUP", ExprOp::Fup},   {"LN", ExprOp::Ln},
          {"EXP", ExprOp::Exp},   {"INT", ExprOp::Fix}};
      bool two = b2 != kNoExpr;
      if (name == "ATAN" || name == "ATAN2" || name == "ATN") {
        if (!two) {
          // one-argument arctangent = ATAN[a]/[1]
          b2 = number(b_, 1.0, static_cast<std::uint32_t>(start + 1));
        }
        result = add(ExprOp::Atan, start, a, b2);
      } else if (two) {
        fail(start, name + " takes one argument");
      } else if (name == "POT") {
        result = add(ExprOp::Times, start, a, a);
      } else if (name == "TRUNC") {
        // toward zero: FIX(a) + (a < 0 AND a <> FIX(a))
        ExprRef fix = add(ExprOp::Fix, start, a);
        ExprRef zero = number(b_, 0.0, static_cast<std::uint32_t>(start + 1));
        ExprRef negative = add(ExprOp::Lt, start, a, zero);
        ExprRef fraction = add(ExprOp::Ne, start, a, fix);
        result = add(ExprOp::Plus, start, fix, add(ExprOp::And, start, negative, fraction));
      } else {
        for (const auto& [n, op] : kUnary) {
          if (n == name) result = add(op, start, a);
        }
        if (result == kNoExpr) fail(start, "Unknown function " + name);
      }
    }
  }
  --depth_;
  return result;
}

}  // namespace ncbridge::interpreter::lowering
