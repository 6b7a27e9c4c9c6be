#pragma once
// Reading one Heidenhain conversational block (BEGIN PGM, TOOL CALL, CYCL DEF/CALL, LBL, FN, Q
// formulas, path functions with their words) into a small word list with expression trees, with
// the column of every word for errors.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "block_model.hpp"
#include "lowering/infix_expression.hpp"
#include "lowering/line_segment.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter::heidenhain {

using lowering::InfixParser;

// One word of a block: FMAX, X+10, IX-5, DR-, R0, Q1 (a variable as value), M3, ...
struct HWord {
  std::string name;            // upper case
  ExprRef value = kNoExpr;     // kNoExpr: no value
  char sign = 0;               // '+'/'-' when the word is only a sign (DR-)
  std::uint32_t column = 0;
};

enum class Kind {
  Empty, Comment, BeginPgm, EndPgm, BlkForm, ToolCall, ToolDef, CyclDef, CyclCall, Label, CallLabel, CallPgm,
  Assign, FnJump, Stop, Path, TchProbe,
  Functions,  // a block of M functions only (`9 M5`, `M5 M9`), as Fusion's post writes at tool changes
  SysRead     // FN 18: SYSREAD Qn = IDa NRb IDXc (words ID, NR, IDX)
};

struct HBlock {
  Kind kind = Kind::Empty;
  std::string keyword;         // path function (L, C, CC, ...), cycle number text ("200", "1.1")
  std::string text;            // rest of line (BEGIN PGM units, CYCL DEF text, label name, comment)
  std::vector<HWord> words;
  Block exprs;                 // expression arena (and assignment target/value)
  ExprRef target = kNoExpr, value = kNoExpr;  // Assign / FnJump comparison operands
  ExprRef value2 = kNoExpr;
  std::string op;              // FnJump comparison
  std::int64_t n = -1;
  std::uint32_t column = 1;    // of the keyword
  bool label_is_name = false;
  double label_number = 0;
  std::string tool_name;       // TOOL CALL "name"
  std::vector<std::pair<ExprRef, ExprRef>> parameters;  // CYCL DEF: Q200=+2 ... (target, value)
};

inline std::string up(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = lowering::upper(c);
  return r;
}

class Reader {
 public:
  Reader() {
    syntax_.open = '(';
    syntax_.close = ')';
    syntax_.word_comparisons = false;
    syntax_.symbol_comparisons = false;
    syntax_.variable = [](std::string_view s, std::size_t& pos, Block& b) -> ExprRef {
      std::size_t p = pos;
      if (p >= s.size() || lowering::upper(s[p]) != 'Q') return kNoExpr;
      ++p;
      std::string name = "_q";
      if (p < s.size() && (lowering::upper(s[p]) == 'L' || lowering::upper(s[p]) == 'R' || lowering::upper(s[p]) == 'S')) {
        name.push_back(static_cast<char>(lowering::upper(s[p]) - 'A' + 'a'));
        ++p;
      }
      std::size_t digits = p;
      while (p < s.size() && lowering::is_digit(s[p])) name.push_back(s[p++]);
      if (p == digits) return kNoExpr;
      const auto column = static_cast<std::uint32_t>(pos + 1);
      pos = p;
      return b.add_named_parameter(name, column);
    };
  }

  // `segments`: where the parts of a block joined from several lines come from (errors name them).
  void read(std::string_view s, std::uint32_t line, const std::string& file, HBlock& out,
            const std::vector<lowering::LineSegment>* segments = nullptr) {
    s_ = s;
    pos_ = 0;
    line_ = line;
    file_ = &file;
    segments_ = segments;
    out = HBlock{};
    out.exprs.line = line;
    skip();
    if (pos_ >= s_.size()) return;
    if (s_[pos_] == ';' || s_[pos_] == '*') {
      out.kind = Kind::Comment;
      out.text = std::string(s_.substr(pos_ + 1));
      return;
    }
    if (lowering::is_digit(s_[pos_])) {
      std::int64_t n = 0;
      while (pos_ < s_.size() && lowering::is_digit(s_[pos_]) && n < 100000000) n = n * 10 + (s_[pos_++] - '0');
      out.n = n;
      skip();
      if (pos_ >= s_.size()) return;
    }
    out.column = static_cast<std::uint32_t>(pos_ + 1);
    if (s_[pos_] == ';' || s_[pos_] == '*') {
      out.kind = Kind::Comment;
      out.text = std::string(s_.substr(pos_ + 1));
      return;
    }
    // strip a trailing `;comment` and `~` continuation marks
    std::size_t semi = find_comment_start();
    if (semi != std::string_view::npos) s_ = s_.substr(0, semi);
    if (keyword("BEGIN PGM")) {
      out.kind = Kind::BeginPgm;
      out.text = up(s_.substr(pos_));
    } else if (keyword("END PGM")) {
      out.kind = Kind::EndPgm;
    } else if (keyword("BLK FORM")) {
      out.kind = Kind::BlkForm;
    } else if (keyword("TOOL CALL") || keyword("TOOL DEF")) {
      out.kind = up(s_.substr(out.column - 1, 6)) == "TOOL C" ? Kind::ToolCall : Kind::ToolDef;
      skip();
      if (pos_ < s_.size() && s_[pos_] == '"') {
        std::size_t close = s_.find('"', pos_ + 1);
        if (close == std::string_view::npos) fail(pos_, "Tool name not closed by '\"'");
        out.tool_name = std::string(s_.substr(pos_ + 1, close - pos_ - 1));
        pos_ = close + 1;
      } else if (pos_ < s_.size() && (lowering::is_digit(s_[pos_]) || lowering::upper(s_[pos_]) == 'Q')) {
        HWord w;
        w.name = "T";
        w.column = static_cast<std::uint32_t>(pos_ + 1);
        w.value = value(out.exprs);
        out.words.push_back(w);
      }
      skip();
      if (pos_ < s_.size() && (lowering::upper(s_[pos_]) == 'X' || lowering::upper(s_[pos_]) == 'Y' ||
                               lowering::upper(s_[pos_]) == 'Z') &&
          (pos_ + 1 >= s_.size() || s_[pos_ + 1] == ' ')) {
        out.text = std::string(1, lowering::upper(s_[pos_]));  // tool axis
        ++pos_;
      }
      words(out);
    } else if (keyword("CYCL DEF")) {
      out.kind = Kind::CyclDef;
      skip();
      std::size_t start = pos_;
      while (pos_ < s_.size() && (lowering::is_digit(s_[pos_]) || s_[pos_] == '.')) ++pos_;
      if (start == pos_) fail(start, "CYCL DEF needs a cycle number");
      out.keyword = std::string(s_.substr(start, pos_ - start));
      out.column = static_cast<std::uint32_t>(start + 1);
      // the cycle's name, then (a block continued with `~`) its parameters Q200=+2 Q201=-12 ...
      std::size_t q = pos_;
      while (q < s_.size() && !(lowering::upper(s_[q]) == 'Q' && (q == 0 || s_[q - 1] == ' ') && assignment_at(q))) ++q;
      out.text = up(s_.substr(pos_, q - pos_));
      pos_ = q;
      while (skip(), pos_ < s_.size()) {
        if (!assignment_at(pos_)) fail(pos_, "Cycle parameter (Qn=value) expected");
        ExprRef target = syntax_.variable(s_, pos_, out.exprs);
        skip();
        ++pos_;  // '='
        out.parameters.emplace_back(target, value(out.exprs));
      }
    } else if (keyword("TCH PROBE")) {  // touch probe cycles: number and text as CYCL DEF
      out.kind = Kind::TchProbe;
      skip();
      std::size_t start = pos_;
      while (pos_ < s_.size() && (lowering::is_digit(s_[pos_]) || s_[pos_] == '.')) ++pos_;
      if (start == pos_) fail(start, "TCH PROBE needs a cycle number");
      out.keyword = std::string(s_.substr(start, pos_ - start));
      out.text = up(s_.substr(pos_));
      out.column = static_cast<std::uint32_t>(start + 1);
      if (out.keyword == "0.1") words(out);  // cycle 0's pre-position: X+5 Y+0 Z-5
    } else if (keyword("CYCL CALL")) {
      out.kind = Kind::CyclCall;
      skip();
      if (keyword("POS")) out.keyword = "POS";
      words(out);
    } else if (keyword("LBL")) {
      out.kind = Kind::Label;
      label(out);
    } else if (keyword("CALL LBL")) {
      out.kind = Kind::CallLabel;
      label(out);
      skip();
      if (keyword("REP")) {
        HWord w;
        w.name = "REP";
        w.column = static_cast<std::uint32_t>(pos_ + 1);
        skip();
        w.value = value(out.exprs);
        out.words.push_back(w);
      }
      skip();
      if (pos_ < s_.size()) fail(pos_, "Unexpected text after CALL LBL");
    } else if (keyword("CALL PGM")) {
      out.kind = Kind::CallPgm;
      skip();
      out.text = std::string(s_.substr(pos_));
      while (!out.text.empty() && out.text.back() == ' ') out.text.pop_back();
    } else if (keyword("FN")) {
      fn(out);
    } else if (keyword("STOP")) {
      out.kind = Kind::Stop;
      words(out);
    } else if (lowering::upper(s_[pos_]) == 'Q' && assignment_follows()) {
      out.kind = Kind::Assign;
      assignment(out);
    } else if (lowering::upper(s_[pos_]) == 'M' && pos_ + 1 < s_.size() && lowering::is_digit(s_[pos_ + 1])) {
      out.kind = Kind::Functions;
      words(out);
    } else {
      static constexpr std::string_view kPaths[] = {"APPR", "DEP", "RND", "CHF", "CC", "CR", "CT", "CP", "LP", "L", "C"};
      for (std::string_view p : kPaths) {
        std::size_t save = pos_;
        if (keyword(p) && (pos_ >= s_.size() || s_[pos_] == ' ' || s_[pos_] == '\t')) {
          out.kind = Kind::Path;
          out.keyword = std::string(p);
          words(out);
          return;
        }
        pos_ = save;
      }
      fail(pos_, "Unknown Heidenhain block '" + std::string(s_.substr(pos_, 12)) + "'");
    }
  }

 private:
  [[noreturn]] void fail(std::size_t at, const std::string& message) const {
    static const std::vector<lowering::LineSegment> kNone;
    throw InputError(lowering::locate(*file_, line_, static_cast<std::uint32_t>(at + 1), segments_ ? *segments_ : kNone),
                     message);
  }
  void skip() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '~')) ++pos_;
  }
  std::size_t find_comment_start() const {
    bool quoted = false;
    for (std::size_t i = pos_; i < s_.size(); ++i) {
      if (s_[i] == '"') quoted = !quoted;
      if (!quoted && s_[i] == ';') return i;
    }
    return std::string_view::npos;
  }
  // A keyword of one or more space-separated parts, case-insensitive.
  bool keyword(std::string_view word) {
    std::size_t p = pos_;
    for (char c : word) {
      if (c == ' ') {
        if (p >= s_.size() || (s_[p] != ' ' && s_[p] != '\t')) return false;
        while (p < s_.size() && (s_[p] == ' ' || s_[p] == '\t')) ++p;
        continue;
      }
      if (p >= s_.size() || lowering::upper(s_[p]) != c) return false;
      ++p;
    }
    pos_ = p;
    return true;
  }
  // A Q, QL or QR parameter starts at `p` (a value written right after its address: FQ4).
  bool q_parameter_at(std::size_t p) const {
    if (p + 1 >= s_.size() || lowering::upper(s_[p]) != 'Q') return false;
    std::size_t d = p + 1;
    if (lowering::upper(s_[d]) == 'L' || lowering::upper(s_[d]) == 'R') ++d;
    return d < s_.size() && lowering::is_digit(s_[d]);
  }
  bool assignment_follows() const { return assignment_at(pos_); }
  // `Qn =` (or QLn, QRn) at p.
  bool assignment_at(std::size_t at) const {
    if (!q_parameter_at(at)) return false;
    std::size_t p = at + 1;
    while (p < s_.size() && (lowering::is_alpha(s_[p]) || lowering::is_digit(s_[p]))) ++p;
    while (p < s_.size() && s_[p] == ' ') ++p;
    return p < s_.size() && s_[p] == '=';
  }
  ExprRef formula(Block& b) {
    InfixParser parser(s_, pos_, b, syntax_, *file_, line_);
    ExprRef r = parser.expression();
    pos_ = parser.position();
    return r;
  }
  ExprRef value(Block& b) {
    skip();
    InfixParser parser(s_, pos_, b, syntax_, *file_, line_);
    ExprRef r = parser.primary();
    pos_ = parser.position();
    return r;
  }
  void label(HBlock& out) {
    skip();
    if (pos_ < s_.size() && s_[pos_] == '"') {
      std::size_t close = s_.find('"', pos_ + 1);
      if (close == std::string_view::npos) fail(pos_, "Label name not closed by '\"'");
      out.label_is_name = true;
      out.text = up(s_.substr(pos_ + 1, close - pos_ - 1));
      pos_ = close + 1;
      return;
    }
    double n = 0;
    std::size_t p = pos_;
    if (!lowering::read_decimal(s_, p, n)) {
      // a label name without quotes (LBL NAME)
      std::size_t start = pos_;
      while (pos_ < s_.size() && s_[pos_] != ' ') ++pos_;
      if (start == pos_) fail(start, "Label number or name missing");
      out.label_is_name = true;
      out.text = up(s_.substr(start, pos_ - start));
      return;
    }
    out.label_number = n;
    pos_ = p;
  }
  void assignment(HBlock& out) {
    out.target = syntax_.variable(s_, pos_, out.exprs);
    if (out.target == kNoExpr) fail(pos_, "Q parameter expected");
    skip();
    if (pos_ >= s_.size() || s_[pos_] != '=') fail(pos_, "'=' missing in Q parameter assignment");
    ++pos_;
    skip();
    out.value = formula(out.exprs);
    skip();
    if (pos_ < s_.size()) fail(pos_, "Unexpected text after the formula");
  }
  // FN 0: Q1 = a   FN 1..4: Q1 = a op b   FN 9..12: IF a cmp b GOTO LBL n
  void fn(HBlock& out) {
    skip();
    double number = 0;
    std::size_t p = pos_;
    if (!lowering::read_decimal(s_, p, number)) fail(pos_, "FN needs a function number");
    pos_ = p;
    skip();
    if (pos_ < s_.size() && s_[pos_] == ':') ++pos_;
    skip();
    int fnum = static_cast<int>(number);
    if (fnum >= 0 && fnum <= 4) {
      out.kind = Kind::Assign;
      out.target = syntax_.variable(s_, pos_, out.exprs);
      if (out.target == kNoExpr) fail(pos_, "Q parameter expected");
      skip();
      if (pos_ >= s_.size() || s_[pos_] != '=') fail(pos_, "'=' missing in FN assignment");
      ++pos_;
      ExprRef a = value(out.exprs);
      if (fnum == 0) {
        out.value = a;
        return;
      }
      skip();
      static constexpr ExprOp kOps[] = {ExprOp::Plus, ExprOp::Minus, ExprOp::Times, ExprOp::Divide};
      std::size_t at = pos_;
      if (fnum == 4) {
        if (!keyword("DIV")) fail(pos_, "FN 4 needs DIV");
      } else {
        if (pos_ >= s_.size()) fail(pos_, "Operator missing in FN");
        ++pos_;
      }
      ExprRef b = value(out.exprs);
      ExprNode node;
      node.op = kOps[fnum - 1];
      node.a = a;
      node.b = b;
      node.column = static_cast<std::uint32_t>(at + 1);
      out.exprs.nodes.push_back(node);
      out.value = static_cast<ExprRef>(out.exprs.nodes.size() - 1);
      return;
    }
    if (fnum == 18) {
      // FN 18: SYSREAD Q10 = ID50 NR2 IDX11 (each number may be a Q parameter: IDXQ11)
      if (!keyword("SYSREAD")) fail(pos_, "FN 18 needs SYSREAD");
      skip();
      out.kind = Kind::SysRead;
      out.target = syntax_.variable(s_, pos_, out.exprs);
      if (out.target == kNoExpr) fail(pos_, "Q parameter expected");
      skip();
      if (pos_ >= s_.size() || s_[pos_] != '=') fail(pos_, "'=' missing in FN 18");
      ++pos_;
      for (;;) {
        skip();
        if (pos_ >= s_.size()) break;
        HWord w;
        w.column = static_cast<std::uint32_t>(pos_ + 1);
        if (keyword("IDX")) w.name = "IDX";
        else if (keyword("ID")) w.name = "ID";
        else if (keyword("NR")) w.name = "NR";
        else fail(pos_, "FN 18 takes ID, NR and IDX");
        w.value = value(out.exprs);
        out.words.push_back(w);
      }
      return;
    }
    if (fnum >= 9 && fnum <= 12) {
      out.kind = Kind::FnJump;
      if (!keyword("IF")) fail(pos_, "FN " + std::to_string(fnum) + " needs IF");
      out.value = value(out.exprs);
      skip();
      static constexpr std::string_view kCmp[] = {"EQU", "NE", "GT", "LT"};
      if (!keyword(kCmp[fnum - 9])) fail(pos_, "FN " + std::to_string(fnum) + " needs " + std::string(kCmp[fnum - 9]));
      out.op = std::string(kCmp[fnum - 9]);
      out.value2 = value(out.exprs);
      skip();
      if (!keyword("GOTO")) fail(pos_, "GOTO missing in FN jump");
      skip();
      if (!keyword("LBL")) fail(pos_, "LBL missing in FN jump");
      label(out);
      return;
    }
    fail(out.column - 1, "FN " + std::to_string(fnum) + " is not supported (FN 0-4, FN 9-12 and FN 18 are)");
  }
  void words(HBlock& out) {
    for (;;) {
      skip();
      if (pos_ >= s_.size()) return;
      std::size_t start = pos_;
      if (out.keyword == "CHF" && out.words.empty() &&
          (lowering::is_digit(s_[pos_]) || s_[pos_] == '.' || s_[pos_] == '+' || s_[pos_] == 'Q')) {
        HWord size;  // CHF 2: the chamfer length has no address
        size.column = static_cast<std::uint32_t>(start + 1);
        size.value = value(out.exprs);
        out.words.push_back(size);
        continue;
      }
      if (!lowering::is_alpha(s_[pos_])) fail(start, std::string("Unexpected character '") + s_[pos_] + "'");
      std::string name;
      while (pos_ < s_.size() && lowering::is_alpha(s_[pos_])) {
        name.push_back(lowering::upper(s_[pos_++]));
        // stop before a Q variable used as the value (X+Q1 is handled by the sign; XQ1 is not TNC)
        if (name == "FMAX" || name == "FAUTO") break;
        if (q_parameter_at(pos_)) break;  // FQ4: the feed from Q4
      }
      HWord w;
      w.name = name;
      w.column = static_cast<std::uint32_t>(start + 1);
      if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) {
        std::size_t after = pos_ + 1;
        if (after >= s_.size() || s_[after] == ' ' || s_[after] == '\t') {
          w.sign = s_[pos_];
          pos_ = after;
          out.words.push_back(w);
          continue;
        }
      }
      if (pos_ < s_.size() && (lowering::is_digit(s_[pos_]) || s_[pos_] == '.' || s_[pos_] == '+' ||
                               s_[pos_] == '-' || s_[pos_] == '(' || lowering::upper(s_[pos_]) == 'Q')) {
        w.value = value(out.exprs);
      }
      out.words.push_back(w);
    }
  }

  lowering::ExpressionSyntax syntax_;
  std::string_view s_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 0;
  const std::string* file_ = nullptr;
  const std::vector<lowering::LineSegment>* segments_ = nullptr;
};

}  // namespace ncbridge::interpreter::heidenhain
