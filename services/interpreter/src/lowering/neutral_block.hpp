#pragma once
// What a dialect's lowering hands the RS274 executor: plain RS274 words with evaluated values
// (G and M codes, axis words in executor coordinates, F, S, T, ...), each with the column of the
// dialect text it came from, and an optional comment or operator message.
#include <cstdint>
#include <string>
#include <vector>

namespace ncbridge::interpreter::lowering {

struct NeutralWord {
  char letter;  // lower case
  double value;
  std::uint32_t column;
};

struct NeutralBlock {
  std::vector<NeutralWord> words;
  std::string comment;
  bool has_comment = false;
  bool comment_is_message = false;

  void add(char letter, double value, std::uint32_t column) { words.push_back({letter, value, column}); }
  void g(double code, std::uint32_t column) { add('g', code, column); }
  void m(int code, std::uint32_t column) { add('m', code, column); }
  bool has(char letter) const {
    for (const auto& w : words) if (w.letter == letter) return true;
    return false;
  }
  bool empty() const { return words.empty() && !has_comment; }
  void clear() {
    words.clear();
    comment.clear();
    has_comment = comment_is_message = false;
  }
};

}  // namespace ncbridge::interpreter::lowering
