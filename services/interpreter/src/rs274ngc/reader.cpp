#include "rs274ngc/reader.hpp"

#include <string>

#include "decimal_text.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter::rs274ngc {

namespace {

char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_alpha(char c) { c = lower(c); return c >= 'a' && c <= 'z'; }

struct Keyword { std::string_view text; ExprOp op; int precedence; };

class LineParser {
 public:
  LineParser(std::string_view text, std::uint32_t line, const std::string& file, Block& block)
      : s_(text), line_(line), file_(file), b_(block) {}

  void parse(bool control_only) {
    b_.line = line_;
    skip_space();
    if (pos_ < s_.size() && s_[pos_] == '%') {
      b_.percent = true;
      return;
    }
    if (pos_ < s_.size() && s_[pos_] == '/') {
      b_.block_delete = true;
      ++pos_;
      skip_space();
    }
    if (pos_ < s_.size() && lower(s_[pos_]) == 'n') read_n_number();
    skip_space();
    if (pos_ < s_.size() && lower(s_[pos_]) == 'o') {
      read_o_word();
    } else if (control_only) {
      return;
    }
    while (skip_space(), pos_ < s_.size()) read_item();
  }

 private:
  [[noreturn]] void fail(std::size_t at, const std::string& message) const {
    throw InputError({file_, line_, static_cast<std::uint32_t>(at + 1)}, message);
  }

  void skip_space() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\r')) ++pos_;
  }
  bool at_end() { skip_space(); return pos_ >= s_.size(); }
  char peek() { skip_space(); return pos_ < s_.size() ? lower(s_[pos_]) : '\0'; }

  // Reads a run of letters (spaces between them allowed, as LinuxCNC strips all spaces).
  std::string_view letters(char* buf, std::size_t cap) {
    std::size_t n = 0;
    while (true) {
      skip_space();
      if (pos_ >= s_.size() || !is_alpha(s_[pos_]) || n == cap) break;
      buf[n++] = lower(s_[pos_++]);
    }
    return {buf, n};
  }

  bool match(std::string_view word) {
    std::size_t save = pos_;
    for (char c : word) {
      skip_space();
      if (pos_ >= s_.size() || lower(s_[pos_]) != c) {
        pos_ = save;
        return false;
      }
      ++pos_;
    }
    return true;
  }

  void read_n_number() {
    std::size_t start = pos_;
    ++pos_;
    skip_space();
    std::int64_t n = 0;
    std::uint8_t digits = 0;
    while (pos_ < s_.size() && is_digit(s_[pos_])) {
      if (n > 99999999999LL) fail(start, "Line number too large");
      n = n * 10 + (s_[pos_] - '0');
      ++digits;
      ++pos_;
    }
    if (digits == 0) fail(start, "Bad format unsigned integer");
    // LinuxCNC accepts (and ignores) a fraction on the N word, e.g. N10.1
    if (pos_ < s_.size() && s_[pos_] == '.') {
      ++pos_;
      while (pos_ < s_.size() && is_digit(s_[pos_])) ++pos_;
    }
    b_.n_number = n;
    b_.n_digits = digits;
  }

  ExprRef add(ExprNode node) {
    b_.nodes.push_back(node);
    return static_cast<ExprRef>(b_.nodes.size() - 1);
  }

  // `<name>`: lower case, spaces removed; returns [begin, length) in the names pool.
  std::pair<std::uint32_t, std::uint32_t> read_name() {
    std::size_t start = pos_;
    ++pos_;  // '<'
    auto begin = static_cast<std::uint32_t>(b_.names.size());
    while (pos_ < s_.size() && s_[pos_] != '>') {
      char c = s_[pos_++];
      if (c == ' ' || c == '\t') continue;
      b_.names.push_back(lower(c));
    }
    if (pos_ >= s_.size()) fail(start, "Named parameter not terminated by '>'");
    ++pos_;
    auto length = static_cast<std::uint32_t>(b_.names.size() - begin);
    if (length == 0) fail(start, "Named parameter has an empty name");
    return {begin, length};
  }

  ExprRef read_number() {
    skip_space();
    std::size_t start = pos_;
    bool negative = false;
    if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) {
      negative = s_[pos_] == '-';
      ++pos_;
      skip_space();
    }
    // Digits, one decimal point, and blanks between them (LinuxCNC skips those).
    const std::size_t digits_begin = pos_;
    DecimalDigits digits;
    bool point = false, any = false;
    for (; pos_ < s_.size(); ++pos_) {
      const char c = s_[pos_];
      if (is_digit(c)) {
        any = true;
        digits.digit(c, point);
      } else if (c == '.') {
        if (point) break;
        point = true;
      } else if (c != ' ' && c != '\t') {
        break;
      }
    }
    if (!any) fail(start, "Bad number format");
    double v = 0;
    if (!digits.exact_value(negative, v)) {
      std::string text = negative ? "-" : "";
      for (std::size_t i = digits_begin; i < pos_; ++i) {
        if (s_[i] != ' ' && s_[i] != '\t') text.push_back(s_[i]);
      }
      if (!parse_decimal(text.data(), text.data() + text.size(), v)) fail(start, "Bad number format");
    }
    ExprNode node;
    node.op = ExprOp::Number;
    node.value = v;
    node.column = static_cast<std::uint32_t>(start + 1);
    return add(node);
  }

  ExprRef read_parameter_reference() {
    std::size_t start = pos_;
    ++pos_;  // '#'
    skip_space();
    ExprNode node;
    node.column = static_cast<std::uint32_t>(start + 1);
    if (pos_ < s_.size() && s_[pos_] == '<') {
      auto [begin, length] = read_name();
      node.op = ExprOp::NamedParameter;
      node.name_begin = begin;
      node.name_length = length;
      return add(node);
    }
    if (pos_ >= s_.size()) fail(start, "Missing parameter number after '#'");
    node.op = ExprOp::Parameter;
    node.a = read_real_value();
    return add(node);
  }

  ExprRef read_real_value() {
    skip_space();
    if (pos_ >= s_.size()) fail(pos_, "Missing value at end of line");
    std::size_t start = pos_;
    char c = lower(s_[pos_]);
    if (c == '[') return read_expression();
    if (c == '#') return read_parameter_reference();
    if (c == '+' || c == '-') {
      std::size_t look = pos_ + 1;
      while (look < s_.size() && (s_[look] == ' ' || s_[look] == '\t')) ++look;
      if (look < s_.size() && (is_digit(s_[look]) || s_[look] == '.')) return read_number();
      ++pos_;
      ExprRef operand = read_real_value();
      if (c == '+') return operand;
      ExprNode node;
      node.op = ExprOp::Negate;
      node.a = operand;
      node.column = static_cast<std::uint32_t>(start + 1);
      return add(node);
    }
    if (is_alpha(c)) return read_function();
    if (is_digit(c) || c == '.') return read_number();
    fail(start, std::string("Bad character '") + s_[pos_] + "' where a value was expected");
  }

  // Whether the letters at pos_ name a function (sin[...], atan[...], exists[...]).
  bool function_follows() {
    std::size_t save = pos_;
    char buf[8];
    std::string_view name = letters(buf, sizeof buf);
    pos_ = save;
    for (std::string_view f : {"abs", "acos", "asin", "atan", "cos", "exp", "exists", "fix", "fup", "round",
                               "ln", "sin", "sqrt", "tan", "not"}) {
      if (f == name) return true;
    }
    return false;
  }

  ExprRef read_function() {
    std::size_t start = pos_;
    char buf[8];
    std::string_view name = letters(buf, sizeof buf);
    ExprNode node;
    node.column = static_cast<std::uint32_t>(start + 1);
    static constexpr std::pair<std::string_view, ExprOp> kUnary[] = {
        {"abs", ExprOp::Abs},   {"acos", ExprOp::Acos}, {"asin", ExprOp::Asin},
        {"cos", ExprOp::Cos},   {"exp", ExprOp::Exp},   {"fix", ExprOp::Fix},
        {"fup", ExprOp::Fup},   {"round", ExprOp::Round}, {"ln", ExprOp::Ln},
        {"sin", ExprOp::Sin},   {"sqrt", ExprOp::Sqrt}, {"tan", ExprOp::Tan},
        {"not", ExprOp::Not}};
    if (name == "exists") {
      if (peek() != '[') fail(pos_, "Left bracket missing after EXISTS");
      ++pos_;
      if (peek() != '#') fail(pos_, "EXISTS needs a named parameter, e.g. EXISTS[#<name>]");
      ++pos_;
      skip_space();
      if (pos_ >= s_.size() || s_[pos_] != '<') fail(pos_, "EXISTS needs a named parameter, e.g. EXISTS[#<name>]");
      auto [begin, length] = read_name();
      if (peek() != ']') fail(pos_, "Right bracket missing after EXISTS argument");
      ++pos_;
      node.op = ExprOp::Exists;
      node.name_begin = begin;
      node.name_length = length;
      return add(node);
    }
    if (name == "atan") {
      if (peek() != '[') fail(pos_, "Left bracket missing after unary operation name");
      node.a = read_expression();
      if (peek() != '/') fail(pos_, "Slash missing after first ATAN argument");
      ++pos_;
      if (peek() != '[') fail(pos_, "Left bracket missing after slash with ATAN");
      node.b = read_expression();
      node.op = ExprOp::Atan;
      return add(node);
    }
    for (const auto& [n, op] : kUnary) {
      if (n == name) {
        if (peek() != '[') fail(pos_, "Left bracket missing after unary operation name");
        node.op = op;
        node.a = read_expression();
        return add(node);
      }
    }
    fail(start, "Unknown word starting with " + std::string(1, buf[0]));
  }

  // Reads a binary operator if one is next; returns false at ']'.
  bool read_operator(ExprOp& op, int& precedence, std::size_t& at) {
    skip_space();
    at = pos_;
    if (pos_ >= s_.size()) fail(pos_, "Unclosed expression: missing ']'");
    char c = lower(s_[pos_]);
    if (c == ']') return false;
    switch (c) {
      case '*':
        ++pos_;
        skip_space();
        if (pos_ < s_.size() && s_[pos_] == '*') {
          ++pos_;
          op = ExprOp::Power;
          precedence = 6;
        } else {
          op = ExprOp::Times;
          precedence = 5;
        }
        return true;
      case '/': ++pos_; op = ExprOp::Divide; precedence = 5; return true;
      case '+': ++pos_; op = ExprOp::Plus; precedence = 4; return true;
      case '-': ++pos_; op = ExprOp::Minus; precedence = 4; return true;
      default: break;
    }
    static constexpr Keyword kOps[] = {
        {"mod", ExprOp::Modulo, 5}, {"eq", ExprOp::Eq, 3},  {"ne", ExprOp::Ne, 3},
        {"gt", ExprOp::Gt, 3},      {"ge", ExprOp::Ge, 3},  {"lt", ExprOp::Lt, 3},
        {"le", ExprOp::Le, 3},      {"and", ExprOp::And, 2}, {"or", ExprOp::Or, 2},
        {"xor", ExprOp::Xor, 2}};
    for (const auto& k : kOps) {
      if (match(k.text)) {
        op = k.op;
        precedence = k.precedence;
        return true;
      }
    }
    fail(pos_, "Unknown operation in expression");
  }

  // '[' value { op value } ']' with LinuxCNC precedence, all operators left-associative.
  ExprRef read_expression() {
    skip_space();
    std::size_t open = pos_;
    ++pos_;  // '['
    ExprRef values[32];
    ExprOp ops[32];
    int precs[32];
    std::uint32_t cols[32];
    int nv = 0, no = 0;
    values[nv++] = read_real_value();
    auto reduce = [&]() {
      ExprNode node;
      node.op = ops[no - 1];
      node.column = cols[no - 1];
      node.b = values[--nv];
      node.a = values[--nv];
      --no;
      values[nv++] = add(node);
    };
    for (;;) {
      ExprOp op;
      int prec;
      std::size_t at;
      if (!read_operator(op, prec, at)) break;
      while (no > 0 && precs[no - 1] >= prec) reduce();
      if (no == 31) fail(open, "Expression too deeply nested");
      ops[no] = op;
      precs[no] = prec;
      cols[no] = static_cast<std::uint32_t>(at + 1);
      ++no;
      values[nv++] = read_real_value();
    }
    ++pos_;  // ']'
    while (no > 0) reduce();
    (void)open;
    return values[0];
  }

  void read_comment() {
    std::size_t start = pos_;
    ++pos_;  // '('
    std::size_t close = s_.find(')', pos_);
    if (close == std::string_view::npos) fail(start, "Unclosed comment found");
    std::string_view text = s_.substr(pos_, close - pos_);
    if (text.find('(') != std::string_view::npos) fail(start, "Nested comment found");
    pos_ = close + 1;
    CommentText comment;
    comment.text = text;
    comment.column = static_cast<std::uint32_t>(start + 1);
    // "(MSG," after leading blanks, any case, nothing between MSG and the comma
    std::size_t i = 0;
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    if (text.size() >= i + 4 && lower(text[i]) == 'm' && lower(text[i + 1]) == 's' && lower(text[i + 2]) == 'g' &&
        text[i + 3] == ',') {
      comment.kind = CommentText::Kind::Message;
      comment.text = text.substr(i + 4);
    }
    b_.comments.push_back(comment);
  }

  void read_item() {
    std::size_t start = pos_;
    char c = lower(s_[pos_]);
    if (c == '(') return read_comment();
    if (c == ';') {
      CommentText comment;
      comment.kind = CommentText::Kind::LineEnd;
      comment.text = s_.substr(pos_ + 1);
      comment.column = static_cast<std::uint32_t>(pos_ + 1);
      b_.comments.push_back(comment);
      pos_ = s_.size();
      return;
    }
    if (c == '#') {
      Assignment a;
      a.column = static_cast<std::uint32_t>(start + 1);
      a.target = read_parameter_reference();
      if (peek() != '=') fail(pos_, "Equal sign missing in parameter setting");
      ++pos_;
      a.value = read_real_value();
      b_.assignments.push_back(a);
      return;
    }
    if (is_alpha(c) && c != 'n' && c != 'o') {
      ++pos_;
      if (!at_end() && is_alpha(s_[pos_]) && !function_follows()) {
        fail(start, std::string(1, static_cast<char>(c - 'a' + 'A')) + " word has no value (bad number format)");
      }
      Word w;
      w.letter = c;
      w.column = static_cast<std::uint32_t>(start + 1);
      w.value = read_real_value();
      b_.words.push_back(w);
      return;
    }
    if (c == '@' || c == '^') {  // polar radius and angle (LinuxCNC read_atsign, read_carat)
      ++pos_;
      Word w;
      w.letter = c;
      w.column = static_cast<std::uint32_t>(start + 1);
      w.value = read_real_value();
      b_.words.push_back(w);
      return;
    }
    if (c == 'n') fail(start, "N word (line number) must come first on the line");
    if (c == 'o') fail(start, "O word must come first on the line (after the N word)");
    fail(start, std::string("Bad character used: '") + s_[pos_] + "'");
  }

  void read_o_word() {
    std::size_t start = pos_;
    ++pos_;  // 'o'
    Statement& st = b_.statement;
    st.column = static_cast<std::uint32_t>(start + 1);
    skip_space();
    if (pos_ < s_.size() && s_[pos_] == '<') {
      auto [begin, length] = read_name();
      st.label_is_name = true;
      st.label_begin = begin;
      st.label_length = length;
    } else {
      // a number (possibly computed: o[#1])
      ExprRef label = read_real_value();
      const ExprNode& n = b_.nodes[label];
      if (n.op != ExprOp::Number) fail(start, "Computed O-word labels are not supported");
      st.label_number = n.value;
    }
    char buf[12];
    std::size_t kw_at = (skip_space(), pos_);
    std::string_view kw = letters(buf, sizeof buf);
    static constexpr std::pair<std::string_view, StatementKind> kKinds[] = {
        {"sub", StatementKind::Sub},           {"endsub", StatementKind::EndSub},
        {"call", StatementKind::Call},         {"return", StatementKind::Return},
        {"if", StatementKind::If},             {"elseif", StatementKind::ElseIf},
        {"else", StatementKind::Else},         {"endif", StatementKind::EndIf},
        {"while", StatementKind::While},       {"endwhile", StatementKind::EndWhile},
        {"do", StatementKind::Do},             {"break", StatementKind::Break},
        {"continue", StatementKind::Continue}, {"repeat", StatementKind::Repeat},
        {"endrepeat", StatementKind::EndRepeat}};
    st.kind = StatementKind::None;
    for (const auto& [name, kind] : kKinds) {
      if (name == kw) st.kind = kind;
    }
    if (st.kind == StatementKind::None) fail(kw_at, "Unknown keyword after O word");
    switch (st.kind) {
      case StatementKind::If:
      case StatementKind::ElseIf:
      case StatementKind::While:
      case StatementKind::Repeat:
        if (peek() != '[') fail(pos_, "Left bracket missing after O-word keyword");
        st.condition = read_expression();
        break;
      case StatementKind::Return:
      case StatementKind::EndSub:
      case StatementKind::EndWhile:
        if (peek() == '[') st.condition = read_expression();
        break;
      case StatementKind::Call:
        while (peek() == '[') st.arguments.push_back(read_expression());
        break;
      default:
        break;
    }
    // Only comments may follow a control statement.
    while (!at_end()) {
      char c = lower(s_[pos_]);
      if (c == '(' || c == ';') {
        read_item();
      } else {
        fail(pos_, "Only comments may follow an O-word statement");
      }
    }
  }

  std::string_view s_;
  std::size_t pos_ = 0;
  std::uint32_t line_;
  const std::string& file_;
  Block& b_;
};

}  // namespace

void read_block(std::string_view text, std::uint32_t line, const std::string& file, Block& block,
                bool control_only) {
  block.clear();
  LineParser(text, line, file, block).parse(control_only);
}

}  // namespace ncbridge::interpreter::rs274ngc
