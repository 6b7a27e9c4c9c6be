#pragma once
// Reading one line of a Fanuc or Mach3 program (word-address syntax and custom macro B:
// #variables, [expressions], IF/GOTO/THEN, WHILE/DO/END) into the neutral block model, with
// the column of every word for errors.
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "block_model.hpp"
#include "fanuc/fanuc_front_end.hpp"
#include "lowering/infix_expression.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter::fanuc {

using lowering::ExpressionSyntax;
using lowering::InfixParser;

// One line read: the neutral block model plus what Fanuc needs on top of it.
struct Line {
  Block block;
  std::vector<bool> literal;    // per word: a plain number (subject to least-increment scaling)
  std::vector<bool> had_point;  // per word: written with a decimal point
  bool then_form = false;       // IF [..] THEN <assignment>
  bool program_number = false;  // an O line
  double o_number = 0;
  void clear() {
    block.clear();
    literal.clear();
    had_point.clear();
    then_form = program_number = false;
  }
};

inline ExpressionSyntax fanuc_syntax() {
  ExpressionSyntax syntax;
  syntax.open = '[';
  syntax.close = ']';
  syntax.word_comparisons = true;
  return syntax;
}

class LineReader {
 public:
  LineReader(const Flavour& flavour) : flavour_(flavour), syntax_(fanuc_syntax()) {
    syntax_.variable = [this](std::string_view s, std::size_t& pos, Block& b) -> ExprRef {
      if (s[pos] != '#') return kNoExpr;
      std::size_t at = pos;
      ++pos;
      InfixParser inner(s, pos, b, syntax_, *file_, line_);
      ExprRef number = inner.primary();
      pos = inner.position();
      ExprNode node;
      node.op = ExprOp::Parameter;
      node.a = number;
      node.column = static_cast<std::uint32_t>(at + 1);
      b.nodes.push_back(node);
      return static_cast<ExprRef>(b.nodes.size() - 1);
    };
  }

  void read(std::string_view s, std::uint32_t line, const std::string& file, Line& out) {
    out.clear();
    s_ = s;
    line_ = line;
    file_ = &file;
    out.block.line = line;
    pos_ = 0;
    skip_space();
    if (pos_ < s_.size() && s_[pos_] == '%') {
      out.block.percent = true;
      return;
    }
    if (pos_ < s_.size() && s_[pos_] == '/') {
      out.block.block_delete = true;
      ++pos_;
    }
    while (skip_space(), pos_ < s_.size()) item(out);
  }

 private:
  [[noreturn]] void fail(std::size_t at, const std::string& message) const {
    throw InputError({*file_, line_, static_cast<std::uint32_t>(at + 1)}, message);
  }
  void skip_space() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t')) ++pos_;
  }
  bool keyword(std::string_view word) {
    std::size_t p = pos_;
    for (char c : word) {
      if (p >= s_.size() || lowering::upper(s_[p]) != c) return false;
      ++p;
    }
    pos_ = p;
    return true;
  }
  ExprRef expression(Block& b) {
    InfixParser parser(s_, pos_, b, syntax_, *file_, line_);
    ExprRef r = parser.expression();
    pos_ = parser.position();
    return r;
  }
  ExprRef bracketed(Block& b, const char* what) {
    skip_space();
    if (pos_ >= s_.size() || s_[pos_] != '[') fail(pos_, std::string("'[' expected after ") + what);
    InfixParser parser(s_, pos_, b, syntax_, *file_, line_);
    ExprRef r = parser.primary();
    pos_ = parser.position();
    return r;
  }
  ExprRef value(Block& b, bool& literal, bool& had_point) {
    skip_space();
    std::size_t p = pos_;
    double v = 0;
    if (p < s_.size() && (lowering::is_digit(s_[p]) || s_[p] == '.' || s_[p] == '-' || s_[p] == '+') &&
        lowering::read_decimal(s_, p, v, &had_point)) {
      literal = true;
      ExprRef r = InfixParser::number(b, v, static_cast<std::uint32_t>(pos_ + 1));
      pos_ = p;
      return r;
    }
    literal = false;
    had_point = true;
    InfixParser parser(s_, pos_, b, syntax_, *file_, line_);
    ExprRef r = parser.primary();
    pos_ = parser.position();
    return r;
  }

  void assignment(Line& out) {
    Assignment a;
    a.column = static_cast<std::uint32_t>(pos_ + 1);
    a.target = syntax_.variable(s_, pos_, out.block);
    skip_space();
    if (pos_ >= s_.size() || s_[pos_] != '=') fail(pos_, "'=' missing in variable assignment");
    ++pos_;
    a.value = expression(out.block);
    out.block.assignments.push_back(a);
  }

  void item(Line& out) {
    std::size_t start = pos_;
    char c = s_[pos_];
    Block& b = out.block;
    if (c == '(') {
      std::size_t close = s_.find(')', pos_);
      if (close == std::string_view::npos) fail(start, "Unclosed comment: ')' missing");
      CommentText comment;
      comment.text = s_.substr(pos_ + 1, close - pos_ - 1);
      comment.column = static_cast<std::uint32_t>(start + 1);
      b.comments.push_back(comment);
      pos_ = close + 1;
      return;
    }
    if (c == ';' && flavour_.semicolon_comments) {  // a comment to the end of the line
      CommentText comment;
      comment.kind = CommentText::Kind::LineEnd;
      comment.text = s_.substr(pos_ + 1);
      comment.column = static_cast<std::uint32_t>(start + 1);
      b.comments.push_back(comment);
      pos_ = s_.size();
      return;
    }
    if (c == ';') {  // end of block
      ++pos_;
      skip_space();
      if (pos_ < s_.size() && s_[pos_] != '(') fail(pos_, "Text after the end-of-block ';'");
      return;
    }
    if (c == '#') {
      assignment(out);
      return;
    }
    if (!lowering::is_alpha(c)) fail(start, std::string("Bad character '") + c + "'");
    bool keyword_follows = pos_ + 1 < s_.size() && lowering::is_alpha(s_[pos_ + 1]);
    if (keyword_follows) {
      if (!flavour_.macro_b) fail(start, "Unknown word: this dialect has no macro statements");
      Statement& st = b.statement;
      st.column = static_cast<std::uint32_t>(start + 1);
      if (keyword("IF")) {
        st.kind = StatementKind::If;
        st.condition = bracketed(b, "IF");
        skip_space();
        if (keyword("GOTO")) {
          st.arguments.push_back(value_expr(b));
        } else if (keyword("THEN")) {
          out.then_form = true;
          skip_space();
          if (pos_ >= s_.size() || s_[pos_] != '#') fail(pos_, "THEN must be followed by an assignment");
          assignment(out);
        } else {
          fail(pos_, "IF must be followed by GOTO or THEN");
        }
        return;
      }
      if (keyword("GOTO")) {
        st.kind = StatementKind::Goto;
        st.arguments.push_back(value_expr(b));
        return;
      }
      if (keyword("WHILE")) {
        st.kind = StatementKind::While;
        st.condition = bracketed(b, "WHILE");
        skip_space();
        if (!keyword("DO")) fail(pos_, "WHILE must be followed by DO m");
        st.label_number = loop_id();
        return;
      }
      if (keyword("DO")) {
        st.kind = StatementKind::Do;
        st.label_number = loop_id();
        return;
      }
      if (keyword("END")) {
        st.kind = StatementKind::EndWhile;
        st.label_number = loop_id();
        return;
      }
      fail(start, "Unknown word starting with '" + std::string(1, lowering::upper(c)) + "'");
    }
    ++pos_;
    char letter = static_cast<char>(lowering::upper(c) - 'A' + 'a');
    if (letter == 'n' && b.words.empty() && b.n_number < 0) {
      skip_space();
      double n = 0;
      std::size_t p = pos_;
      if (!lowering::read_decimal(s_, p, n) || n < 0) fail(start, "N must be followed by a sequence number");
      b.n_number = static_cast<std::int64_t>(n);
      b.n_digits = static_cast<std::uint8_t>(p - pos_);
      pos_ = p;
      return;
    }
    if (letter == 'o' && b.words.empty()) {
      skip_space();
      double o = 0;
      std::size_t p = pos_;
      if (!lowering::read_decimal(s_, p, o) || o < 0) fail(start, "O must be followed by a program number");
      out.program_number = true;
      out.o_number = o;
      pos_ = p;
      return;
    }
    if (pos_ >= s_.size()) fail(start, std::string(1, lowering::upper(c)) + " word has no value");
    Word w;
    w.letter = letter;
    w.column = static_cast<std::uint32_t>(start + 1);
    bool literal = false, had_point = false;
    w.value = value(b, literal, had_point);
    b.words.push_back(w);
    out.literal.push_back(literal);
    out.had_point.push_back(had_point);
  }

  ExprRef value_expr(Block& b) {
    bool literal, had_point;
    return value(b, literal, had_point);
  }
  double loop_id() {
    skip_space();
    double id = 0;
    std::size_t p = pos_;
    if (!lowering::read_decimal(s_, p, id) || id < 1 || id > 3 || id != std::floor(id)) {
      fail(pos_, "Loop identification number must be 1, 2 or 3");
    }
    pos_ = p;
    return id;
  }

  const Flavour& flavour_;
  ExpressionSyntax syntax_;
  std::string_view s_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 0;
  const std::string* file_ = nullptr;
};

// A line that cannot be a block: it starts with a run of two or more letters that is no macro
// keyword, or with a character no block starts with.
inline bool title_line(std::string_view l) {
  std::size_t p = 0;
  while (p < l.size() && (l[p] == ' ' || l[p] == '\t')) ++p;
  if (p >= l.size()) return false;
  std::size_t q = p;
  while (q < l.size() && lowering::is_alpha(l[q])) ++q;
  if (q - p < 2) return !lowering::is_alpha(l[p]) && l[p] != '#' && l[p] != '(' && l[p] != '/' && l[p] != '%' && l[p] != ';';
  std::string word;
  for (std::size_t i = p; i < q; ++i) word.push_back(lowering::upper(l[i]));
  return word != "IF" && word != "GOTO" && word != "WHILE" && word != "END" && word != "DO";
}

}  // namespace ncbridge::interpreter::fanuc
