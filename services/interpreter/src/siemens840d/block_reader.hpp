#pragma once
// Reading one SINUMERIK 840D block (N numbers, labels, address words with = and AC()/IC(),
// calls with argument lists, assignments, DEF, IF/GOTOx, keywords) into items with expression
// trees, with the column of every item for errors.
#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "block_model.hpp"
#include "lowering/infix_expression.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter::siemens840d {

using lowering::InfixParser;

struct Item {
  enum class Kind { Word, Assign, Call, Keyword } kind = Kind::Word;
  std::string name;                 // upper case: X, CR, I1, G, M, R12, _X_HOME, CYCLE81, TRANS, GOTOF
  ExprRef value = kNoExpr;          // Word/Assign value
  char mode = 0;                    // 'A' for =AC(..), 'I' for =IC(..)
  std::vector<ExprRef> arguments;   // Call: kNoExpr for an empty argument
  std::string text;                 // Keyword operand (label), string argument (MSG, T="name")
  // MSG("Depth " << R1 << " mm"): the parts of a string expression, text or a value (kNoExpr
  // marks a text part)
  std::vector<std::pair<std::string, ExprRef>> message;
  std::uint32_t column = 0;
};

struct SBlock {
  Block exprs;
  std::vector<Item> items;
  std::string comment;
  bool has_comment = false;
  std::int64_t n = -1;
  std::string label;                // LABEL: at the start
  // control: IF cond GOTOF label / GOTOF label
  ExprRef condition = kNoExpr;
  // structured control: IF (without GOTO), ELSE, ENDIF, WHILE, ENDWHILE, REPEAT, UNTIL, LOOP,
  // ENDLOOP, FOR var=from TO to, ENDFOR
  std::string control;
  std::uint32_t control_column = 0;
  std::string for_variable;  // the variable's parameter key (_r1, _v_name)
  ExprRef for_from = kNoExpr, for_to = kNoExpr;
  // PROC NAME(INT A, REAL B) (control "PROC"): the parameter names in order; EXTERN
  // declarations (control "EXTERN") declare nothing a reading needs
  std::vector<std::string> proc_parameters;
};

inline std::string up(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = lowering::upper(c);
  return r;
}
inline bool ident_char(char c) { return lowering::is_alpha(c) || lowering::is_digit(c) || c == '_' || c == '$'; }

class Reader {
 public:
  explicit Reader(const std::set<std::string>& variables) : variables_(variables) {
    syntax_.open = '(';
    syntax_.close = ')';
    syntax_.word_comparisons = false;
    syntax_.symbol_comparisons = true;
    syntax_.variable = [this](std::string_view s, std::size_t& pos, Block& b) -> ExprRef {
      std::size_t p = pos;
      if (p >= s.size() || !(lowering::is_alpha(s[p]) || s[p] == '_' || s[p] == '$')) return kNoExpr;
      std::string name;
      while (p < s.size() && ident_char(s[p])) name.push_back(lowering::upper(s[p++]));
      std::string key;
      if (name == "$AA_MW" || name == "$AC_MEA") return measurement(s, pos, p, name, b);
      if (name.size() > 1 && name[0] == 'R' && std::all_of(name.begin() + 1, name.end(), lowering::is_digit)) {
        key = "_r" + name.substr(1);
      } else if (variables_.count(name)) {
        key = variable_key(name);
      } else {
        return kNoExpr;
      }
      const auto column = static_cast<std::uint32_t>(pos + 1);
      pos = p;
      return b.add_named_parameter(key, column);
    };
  }

  // $AC_MEA[n]: 1 once probe n (1, 2) triggered in a MEAS/MEAW block, else 0.
  static std::string measured_key(int probe) { return "_v_$ac_mea_" + std::to_string(probe); }

  static std::string variable_key(const std::string& name) {
    std::string key = "_v_";
    for (char c : name) key.push_back((c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c);
    return key;
  }

  // $AA_MW[axis] (the measured position, workpiece coordinates: LinuxCNC's #5061.. X Y Z A B C)
  // and $AC_MEA[probe], read after MEAS=/MEAW=.
  ExprRef measurement(std::string_view s, std::size_t& pos, std::size_t p, const std::string& name, Block& b) const {
    const auto column = static_cast<std::uint32_t>(pos + 1);
    std::size_t q = p;
    while (q < s.size() && s[q] == ' ') ++q;
    std::size_t close = q < s.size() && s[q] == '[' ? s.find(']', q) : std::string_view::npos;
    if (close == std::string_view::npos) fail(pos, name + " needs an index in brackets");
    std::string index = up(s.substr(q + 1, close - q - 1));
    index.erase(std::remove(index.begin(), index.end(), ' '), index.end());
    pos = close + 1;
    if (name == "$AC_MEA") {
      if (index != "1" && index != "2") fail(q, "$AC_MEA[" + index + "]: the probe is 1 or 2");
      return b.add_named_parameter(measured_key(index == "1" ? 1 : 2), column);
    }
    static constexpr std::string_view kAxes = "XYZABC";
    const std::size_t axis = index.size() == 1 ? kAxes.find(index[0]) : std::string_view::npos;
    if (axis == std::string_view::npos) fail(q, "$AA_MW[" + index + "]: the axis is X, Y, Z, A, B or C");
    ExprNode number;
    number.op = ExprOp::Number;
    number.value = 5061.0 + static_cast<double>(axis);
    number.column = column;
    b.nodes.push_back(number);
    ExprNode parameter;
    parameter.op = ExprOp::Parameter;
    parameter.a = static_cast<ExprRef>(b.nodes.size() - 1);
    parameter.column = column;
    b.nodes.push_back(parameter);
    return static_cast<ExprRef>(b.nodes.size() - 1);
  }

  void read(std::string_view s, std::uint32_t line, const std::string& file, SBlock& out) {
    s_ = s;
    pos_ = 0;
    line_ = line;
    file_ = &file;
    out = SBlock{};
    out.exprs.line = line;
    skip();
    if (pos_ < s_.size() && s_[pos_] == '/') {
      ++pos_;
      skip();
    }
    if (pos_ + 1 < s_.size() && lowering::upper(s_[pos_]) == 'N' && lowering::is_digit(s_[pos_ + 1])) {
      ++pos_;
      std::int64_t n = 0;
      while (pos_ < s_.size() && lowering::is_digit(s_[pos_]) && n < 1000000000) n = n * 10 + (s_[pos_++] - '0');
      out.n = n;
      skip();
    }
    // LABEL:
    {
      std::size_t p = pos_;
      while (p < s_.size() && ident_char(s_[p])) ++p;
      if (p > pos_ && p < s_.size() && s_[p] == ':' && lowering::is_alpha(s_[pos_])) {
        out.label = up(s_.substr(pos_, p - pos_));
        pos_ = p + 1;
      }
    }
    while (skip(), pos_ < s_.size()) item(out);
  }

 private:
  [[noreturn]] void fail(std::size_t at, const std::string& message) const {
    throw InputError({*file_, line_, static_cast<std::uint32_t>(at + 1)}, message);
  }
  void skip() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t')) ++pos_;
  }
  ExprRef expression(Block& b) {
    InfixParser parser(s_, pos_, b, syntax_, *file_, line_);
    ExprRef r = parser.expression();
    pos_ = parser.position();
    return r;
  }
  // After '=': AC(expr), IC(expr) or an expression.
  ExprRef word_value(Block& b, char& mode) {
    skip();
    mode = 0;
    std::string_view rest = s_.substr(pos_);
    if (rest.size() > 2 && (lowering::upper(rest[0]) == 'A' || lowering::upper(rest[0]) == 'I') &&
        lowering::upper(rest[1]) == 'C' && (rest[2] == '(' || rest[2] == ' ')) {
      std::size_t p = pos_ + 2;
      while (p < s_.size() && s_[p] == ' ') ++p;
      if (p < s_.size() && s_[p] == '(') {
        mode = lowering::upper(rest[0]);
        pos_ = p + 1;
        ExprRef r = expression(b);
        skip();
        if (pos_ >= s_.size() || s_[pos_] != ')') fail(pos_, "')' missing after AC(/IC(");
        ++pos_;
        return r;
      }
    }
    return expression(b);
  }

  void item(SBlock& out) {
    std::size_t start = pos_;
    char c = s_[pos_];
    if (c == ';') {
      out.comment = std::string(s_.substr(pos_ + 1));
      out.has_comment = true;
      pos_ = s_.size();
      return;
    }
    if (!(lowering::is_alpha(c) || c == '_' || c == '$')) fail(start, std::string("Unexpected character '") + c + "'");
    std::string name;
    std::size_t p = pos_;
    // an address letter followed by a number: X10, G1, M3, F250., I1.46, L10
    if (lowering::is_alpha(c) && p + 1 < s_.size() &&
        (lowering::is_digit(s_[p + 1]) || s_[p + 1] == '.' || s_[p + 1] == '-' || s_[p + 1] == '+')) {
      // I1=.., J1=.., K1=.., R12=.. (names with digits and '=') are not plain words
      std::size_t q = p + 1;
      while (q < s_.size() && lowering::is_digit(s_[q])) ++q;
      std::size_t r = q;
      while (r < s_.size() && s_[r] == ' ') ++r;
      bool assignment = q > p + 1 && r < s_.size() && s_[r] == '=' && (r + 1 >= s_.size() || s_[r + 1] != '=');
      // L140(2): a subprogram called with arguments, not the word L140
      const bool call = q > p + 1 && r < s_.size() && s_[r] == '(';
      if (!assignment && !call) {
        Item it;
        it.kind = Item::Kind::Word;
        it.name = std::string(1, lowering::upper(c));
        it.column = static_cast<std::uint32_t>(start + 1);
        pos_ = p + 1;
        double v = 0;
        std::size_t vp = pos_;
        if (!lowering::read_decimal(s_, vp, v)) fail(start, it.name + " has a bad number");
        it.value = InfixParser::number(out.exprs, v, static_cast<std::uint32_t>(pos_ + 1));
        pos_ = vp;
        out.items.push_back(it);
        return;
      }
    }
    while (p < s_.size() && ident_char(s_[p])) name.push_back(lowering::upper(s_[p++]));
    pos_ = p;
    skip();
    Item it;
    it.name = name;
    it.column = static_cast<std::uint32_t>(start + 1);
    if ((name == "PROC" || name == "EXTERN") && out.items.empty() && out.control.empty()) {
      declaration(out, name, it.column);
      return;
    }
    if (name == "CALL" && pos_ < s_.size() && (s_[pos_] == '"' || ident_char(s_[pos_]))) {
      // CALL "PART2" / CALL PART2: the named program, as a call of its name
      std::size_t q = pos_;
      if (s_[q] == '"') {
        std::size_t close = s_.find('"', q + 1);
        if (close == std::string_view::npos) fail(q, "Program name not closed by '\"'");
        it.text = std::string(s_.substr(q + 1, close - q - 1));
        pos_ = close + 1;
      } else {
        while (q < s_.size() && (ident_char(s_[q]) || s_[q] == '.')) ++q;
        it.text = std::string(s_.substr(pos_, q - pos_));
        pos_ = q;
      }
      it.kind = Item::Kind::Keyword;
      out.items.push_back(it);
      return;
    }
    if (pos_ < s_.size() && s_[pos_] == '=' && (pos_ + 1 >= s_.size() || s_[pos_ + 1] != '=')) {
      ++pos_;
      skip();
      if (name == "T" && pos_ < s_.size() && s_[pos_] == '"') {
        std::size_t close = s_.find('"', pos_ + 1);
        if (close == std::string_view::npos) fail(pos_, "Tool name not closed by '\"'");
        it.kind = Item::Kind::Word;
        it.text = std::string(s_.substr(pos_ + 1, close - pos_ - 1));
        pos_ = close + 1;
        out.items.push_back(it);
        return;
      }
      bool variable = (name.size() > 1 && name[0] == 'R' && std::all_of(name.begin() + 1, name.end(), lowering::is_digit)) ||
                      variables_.count(name) != 0;
      it.kind = variable ? Item::Kind::Assign : Item::Kind::Word;
      it.value = word_value(out.exprs, it.mode);
      out.items.push_back(it);
      return;
    }
    if (pos_ < s_.size() && s_[pos_] == '(') {
      it.kind = Item::Kind::Call;
      ++pos_;
      for (;;) {
        skip();
        if (pos_ >= s_.size()) fail(start, "')' missing in call of " + name);
        if (s_[pos_] == ')') {
          ++pos_;
          break;
        }
        if (s_[pos_] == ',') {
          it.arguments.push_back(kNoExpr);
          ++pos_;
          continue;
        }
        if (s_[pos_] == '"' || (name == "MSG" && it.arguments.empty())) {
          // a string, or (MSG) a string expression: "text" << R1 << "text"
          for (;;) {
            skip();
            if (pos_ < s_.size() && s_[pos_] == '"') {
              std::size_t close = s_.find('"', pos_ + 1);
              if (close == std::string_view::npos) fail(pos_, "String not closed by '\"'");
              it.message.emplace_back(std::string(s_.substr(pos_ + 1, close - pos_ - 1)), kNoExpr);
              pos_ = close + 1;
            } else {
              // the value runs to the next << (or the end of the argument): parsed on its own
              std::size_t end = pos_;
              int depth = 0;
              while (end < s_.size()) {
                const char ch = s_[end];
                if (ch == '(') ++depth;
                if (ch == ')' && depth-- == 0) break;
                if ((ch == ',' && depth == 0) || (s_.substr(end, 2) == "<<" && depth == 0)) break;
                ++end;
              }
              InfixParser parser(s_.substr(0, end), pos_, out.exprs, syntax_, *file_, line_);
              it.message.emplace_back(std::string(), parser.expression());
              pos_ = parser.position();
            }
            skip();
            if (s_.substr(pos_, 2) != "<<") break;
            pos_ += 2;
          }
          for (const auto& part : it.message) {
            if (part.second == kNoExpr) it.text += part.first;
          }
          if (it.message.size() == 1 && it.message.front().second == kNoExpr) it.message.clear();
          it.arguments.push_back(kNoExpr);  // keeps the positions of the arguments after it
        } else {
          it.arguments.push_back(expression(out.exprs));
        }
        skip();
        if (pos_ < s_.size() && s_[pos_] == ',') {
          ++pos_;
          skip();
          if (pos_ < s_.size() && s_[pos_] == ')') it.arguments.push_back(kNoExpr);
          continue;
        }
        if (pos_ < s_.size() && s_[pos_] == ')') {
          ++pos_;
          break;
        }
        fail(pos_, "',' or ')' expected in the arguments of " + name);
      }
      out.items.push_back(it);
      return;
    }
    it.kind = Item::Kind::Keyword;
    if (name == "IF" || name == "WHILE" || name == "UNTIL") {
      out.condition = expression(out.exprs);
      out.control = name;
      out.control_column = it.column;
      return;
    }
    if (name == "ELSE" || name == "ENDIF" || name == "ENDWHILE" || name == "REPEAT" || name == "LOOP" ||
        name == "ENDLOOP" || name == "ENDFOR") {
      out.control = name;
      out.control_column = it.column;
      return;
    }
    if (name == "FOR") {
      // FOR R1=0 TO 10 / FOR NAME=... TO ...
      skip();
      std::size_t v = pos_;
      while (v < s_.size() && ident_char(s_[v])) ++v;
      std::string var = up(s_.substr(pos_, v - pos_));
      bool r_param = var.size() > 1 && var[0] == 'R' && std::all_of(var.begin() + 1, var.end(), lowering::is_digit);
      if (!r_param && !variables_.count(var)) fail(pos_, "FOR needs an R parameter or a DEF variable");
      out.for_variable = r_param ? "_r" + var.substr(1) : variable_key(var);
      pos_ = v;
      skip();
      if (pos_ >= s_.size() || s_[pos_] != '=') fail(pos_, "'=' missing in FOR");
      ++pos_;
      out.for_from = expression(out.exprs);
      skip();
      if (s_.substr(pos_, 2) != "TO" && s_.substr(pos_, 2) != "to") fail(pos_, "TO missing in FOR");
      pos_ += 2;
      out.for_to = expression(out.exprs);
      out.control = name;
      out.control_column = it.column;
      return;
    }
    if (name == "GOTOF" || name == "GOTOB" || name == "GOTO" || name == "GOTOC") {
      skip();
      std::size_t q = pos_;
      while (q < s_.size() && ident_char(s_[q])) ++q;
      if (q == pos_) fail(pos_, name + " needs a label");
      it.text = up(s_.substr(pos_, q - pos_));
      pos_ = q;
    }
    if (name == "DEF") {
      // DEF REAL A, B=5, C: declares variables (values set by the runner)
      skip();
      std::size_t q = pos_;
      while (q < s_.size() && ident_char(s_[q])) ++q;
      it.text = up(s_.substr(pos_, q - pos_));  // the type
      pos_ = q;
      for (;;) {
        skip();
        std::size_t v = pos_;
        while (v < s_.size() && ident_char(s_[v])) ++v;
        if (v == pos_) fail(pos_, "Variable name expected in DEF");
        Item var;
        var.kind = Item::Kind::Assign;
        var.name = up(s_.substr(pos_, v - pos_));
        var.column = static_cast<std::uint32_t>(pos_ + 1);
        declared_.insert(var.name);
        pos_ = v;
        skip();
        if (pos_ < s_.size() && s_[pos_] == '=') {
          ++pos_;
          var.value = expression(out.exprs);
          skip();
        } else {
          var.value = InfixParser::number(out.exprs, 0.0, var.column);
        }
        var.text = "DEF";
        out.items.push_back(var);
        if (pos_ < s_.size() && s_[pos_] == ',') {
          ++pos_;
          continue;
        }
        break;
      }
      return;
    }
    out.items.push_back(it);
  }

 public:
  std::set<std::string> declared_;  // names a DEF (or PROC) of this block declared

 private:
  // PROC NAME(INT A, REAL B=5, VAR REAL C) SAVE / EXTERN NAME(INT, REAL): the names are
  // declared as variables (the call binds them); types and the rest are not needed.
  void declaration(SBlock& out, const std::string& keyword, std::uint32_t column) {
    out.control = keyword;
    out.control_column = column;
    std::size_t open = s_.find('(', pos_);
    if (open == std::string_view::npos) {
      pos_ = s_.size();
      return;
    }
    std::size_t close = s_.find(')', open);
    if (close == std::string_view::npos) fail(open, "')' missing in " + keyword);
    if (keyword == "PROC") {
      std::string_view list = s_.substr(open + 1, close - open - 1);
      std::size_t i = 0;
      while (i < list.size()) {
        std::size_t comma = list.find(',', i);
        if (comma == std::string_view::npos) comma = list.size();
        std::string_view part = list.substr(i, comma - i);
        std::size_t eq = part.find('=');
        if (eq != std::string_view::npos) part = part.substr(0, eq);
        while (!part.empty() && (part.back() == ' ' || part.back() == '\t')) part.remove_suffix(1);
        std::size_t b = part.size();
        while (b > 0 && ident_char(part[b - 1])) --b;
        std::string name = up(part.substr(b));
        if (!name.empty()) {
          out.proc_parameters.push_back(name);
          declared_.insert(name);
        }
        i = comma + 1;
      }
    }
    pos_ = s_.size();  // SAVE, DISPLOF and the like follow: nothing a reading needs
  }

 public:

 private:
  const std::set<std::string>& variables_;
  lowering::ExpressionSyntax syntax_;
  std::string_view s_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 0;
  const std::string* file_ = nullptr;
};

}  // namespace ncbridge::interpreter::siemens840d
