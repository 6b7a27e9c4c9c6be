#pragma once
// The dialect-neutral block model: what a dialect front-end makes of one line of program text,
// before anything is evaluated or executed.
//
// A Block is one line:
//   - `words`: an address and a value expression each (`X[#1+2]`, `G1`, `M3`). Single-letter
//     addresses use `letter`; dialects with multi-letter addresses (Siemens `CR=`, `AP=`, `RP=`,
//     Heidenhain `FMAX`, `CC`) put the name in `address` (letter 0), and their executor
//     extension gives them meaning (polar coordinates, frames, rotations) before the RS274
//     machine semantics run;
//   - `assignments`: parameter settings (`#1=5`, `#<depth>=-2`, Fanuc `#100=...`, Siemens
//     `R1=...`), all evaluated with the values from before the line, then stored, then the
//     words are executed;
//   - `comments`: plain comments and operator messages, in order;
//   - `statement`: at most one control statement (subroutine definition/call/return, loops,
//     conditionals, labels and jumps), run by the generic control-flow runner;
//   - `block_delete`, `n_number`: the `/` and `N` of the line.
//
// Expressions are trees in the block's node arena, referenced by index. The arena, the name
// pool and all vectors are reused from line to line (Block::clear keeps capacity), so reading
// a program makes no per-word heap allocation once warmed up. Every word and node keeps the
// 1-based column it came from, for error messages.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ncbridge::interpreter {

using ExprRef = std::uint32_t;
constexpr ExprRef kNoExpr = 0xffffffffu;

enum class ExprOp : std::uint8_t {
  Number,          // value
  Parameter,       // numbered parameter; a = expression giving the number
  NamedParameter,  // name = [name_begin, name_begin + name_length) in Block::names
  Exists,          // EXISTS[#<name>]; name as above
  // unary (a = operand)
  Negate, Abs, Acos, Asin, Cos, Exp, Fix, Fup, Round, Ln, Sin, Sqrt, Tan, Not,
  // binary (a = left, b = right); Atan is ATAN[a]/[b]
  Atan, Power, Times, Divide, Modulo, Plus, Minus,
  Eq, Ne, Gt, Ge, Lt, Le, And, Or, Xor,
};

struct ExprNode {
  ExprOp op = ExprOp::Number;
  std::uint32_t column = 0;
  ExprRef a = kNoExpr, b = kNoExpr;
  double value = 0;
  std::uint32_t name_begin = 0, name_length = 0;
};

struct Word {
  char letter = 0;                            // lower case, '@'/'^' (polar radius/angle);
                                              // 0 when `address` is used
  std::uint32_t address_begin = 0, address_length = 0;  // multi-letter address in Block::names
  ExprRef value = kNoExpr;
  std::uint32_t column = 0;
};

struct Assignment {
  ExprRef target = kNoExpr;  // a Parameter or NamedParameter node
  ExprRef value = kNoExpr;
  std::uint32_t column = 0;
};

struct CommentText {
  enum class Kind : std::uint8_t { Plain, Message, LineEnd };  // LineEnd: a `;` comment
  Kind kind = Kind::Plain;
  std::string_view text;  // points into the line, valid while the block is
  std::uint32_t column = 0;
};

enum class StatementKind : std::uint8_t {
  None,
  Sub, EndSub, Call, Return,
  If, ElseIf, Else, EndIf,
  While, EndWhile, Do, Break, Continue,
  Repeat, EndRepeat,
  Label, Goto,  // for dialects with jump labels (Fanuc GOTO n, Heidenhain LBL); unused by RS274
};

struct Statement {
  StatementKind kind = StatementKind::None;
  // The label: a number, or a name in Block::names (lower case). Named labels have
  // label_is_name set; numbered labels keep the number in `label_number`.
  bool label_is_name = false;
  double label_number = 0;
  std::uint32_t label_begin = 0, label_length = 0;
  ExprRef condition = kNoExpr;   // if/elseif/while/repeat count/return value
  std::vector<ExprRef> arguments;  // call arguments
  std::uint32_t column = 0;
};

struct Block {
  std::uint32_t line = 0;          // 1-based
  bool block_delete = false;
  bool percent = false;            // a `%` line (program delimiter)
  std::int64_t n_number = -1;
  std::uint8_t n_digits = 0;
  std::vector<Word> words;
  std::vector<Assignment> assignments;
  std::vector<CommentText> comments;
  Statement statement;
  std::vector<ExprNode> nodes;
  std::string names;

  std::string_view name(std::uint32_t begin, std::uint32_t length) const {
    return std::string_view(names).substr(begin, length);
  }
  std::string_view label() const { return name(statement.label_begin, statement.label_length); }

  // A NamedParameter node reading the parameter `parameter_name` (written at 1-based `column`).
  ExprRef add_named_parameter(std::string_view parameter_name, std::uint32_t column) {
    ExprNode node;
    node.op = ExprOp::NamedParameter;
    node.column = column;
    node.name_begin = static_cast<std::uint32_t>(names.size());
    node.name_length = static_cast<std::uint32_t>(parameter_name.size());
    names += parameter_name;
    nodes.push_back(node);
    return static_cast<ExprRef>(nodes.size() - 1);
  }

  void clear() {
    line = 0;
    block_delete = percent = false;
    n_number = -1;
    n_digits = 0;
    words.clear();
    assignments.clear();
    comments.clear();
    statement.kind = StatementKind::None;
    statement.label_is_name = false;
    statement.condition = kNoExpr;
    statement.arguments.clear();
    nodes.clear();
    names.clear();
  }
};

}  // namespace ncbridge::interpreter
