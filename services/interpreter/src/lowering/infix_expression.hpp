#pragma once
// Infix expressions as the controller dialects write them (Fanuc custom macro B `#1+SIN[30]*2`,
// Siemens `R1*(R2+3)`, `A==B`, Heidenhain `Q1 = Q2 * (Q3 + 1)`), parsed into the neutral block
// model's expression nodes, so the shared evaluator gives them one meaning.
//
// Precedence (all dialects agree): unary minus/NOT, then * / MOD DIV, then + -, then
// comparisons, then AND, then OR/XOR. Functions take their argument in the dialect's brackets.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "block_model.hpp"

namespace ncbridge::interpreter::lowering {

struct ExpressionSyntax {
  char open = '[';
  char close = ']';
  bool word_comparisons = true;    // EQ NE GT GE LT LE (Fanuc)
  bool symbol_comparisons = false; // == <> > >= < <= (Siemens)
  // Resolves a variable at text[pos]: returns the node made and advances pos, or kNoExpr when
  // the text there is not a variable of the dialect. Called before identifiers are tried as
  // function names.
  std::function<ExprRef(std::string_view text, std::size_t& pos, Block& block)> variable;
};

class InfixParser {
 public:
  InfixParser(std::string_view text, std::size_t pos, Block& block, const ExpressionSyntax& syntax,
              const std::string& file, std::uint32_t line);

  ExprRef expression();  // a whole expression
  ExprRef primary();     // one operand (number, variable, function, bracketed expression, sign)
  std::size_t position() const { return pos_; }
  [[noreturn]] void fail(std::size_t at, const std::string& message) const;

  // Adds a number node.
  static ExprRef number(Block& block, double value, std::uint32_t column);

 private:
  ExprRef binary(int level);
  bool operator_at(int level, ExprOp& op);
  void skip_space();
  ExprRef add(ExprOp op, std::size_t at, ExprRef a, ExprRef b = kNoExpr);

  std::string_view s_;
  std::size_t pos_;
  Block& b_;
  const ExpressionSyntax& syntax_;
  const std::string& file_;
  std::uint32_t line_;
  int depth_ = 0;
};

// Reads an unsigned/signed decimal number at text[pos] ("12", "-3.5", ".5", "+7."); false when
// there is none. `had_point` tells whether a decimal point was written (Fanuc scales
// dimension words written without one).
bool read_decimal(std::string_view text, std::size_t& pos, double& value, bool* had_point = nullptr);

char upper(char c);
bool is_alpha(char c);
bool is_digit(char c);

}  // namespace ncbridge::interpreter::lowering
