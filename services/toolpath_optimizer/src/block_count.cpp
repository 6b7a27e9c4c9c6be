// Counting commands and motion blocks of CNC program text (block_count.hpp).
#include "ncbridge/toolpath_optimizer/block_count.hpp"

#include <cctype>
#include <cstdlib>

namespace ncbridge::toolpath_optimizer {

namespace {

char up(char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); }
bool digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

void BlockCounter::text(std::string_view piece) {
  counts_.bytes += piece.size();
  std::size_t begin = 0;
  for (;;) {
    const std::size_t nl = piece.find('\n', begin);
    if (nl == std::string_view::npos) break;
    if (pending_.empty()) {
      line(piece.substr(begin, nl - begin));
    } else {
      pending_.append(piece.substr(begin, nl - begin));
      line(pending_);
      pending_.clear();
    }
    begin = nl + 1;
  }
  pending_.append(piece.substr(begin));
}

const BlockCounts& BlockCounter::finish() {
  if (!pending_.empty()) line(pending_);
  pending_.clear();
  return counts_;
}

void BlockCounter::line(std::string_view raw) {
  ++counts_.lines;
  // Code without comments: ; to the end, ( ... ) pairs.
  std::string code;
  code.reserve(raw.size());
  int paren = 0;
  for (char c : raw) {
    if (c == ';' && paren == 0) break;
    if (c == '(') ++paren;
    else if (c == ')' && paren > 0) --paren;
    else if (paren == 0 && c != '\r' && c != '\t' && c != ' ') code.push_back(up(c));
  }
  if (code.empty() || code == "%") return;
  ++counts_.commands;
  if (heidenhain_) {
    // Block number, then the function.
    std::size_t i = 0;
    while (i < code.size() && digit(code[i])) ++i;
    const std::string_view f(code.data() + i, code.size() - i);
    auto starts = [&](std::string_view p) { return f.compare(0, p.size(), p) == 0; };
    if (starts("CALL") || starts("CYCL") || starts("CC")) return;
    if (starts("LP") || starts("LBL") ) {
      if (starts("LP")) ++counts_.motion_blocks;
      return;
    }
    if (starts("L") || starts("RND") || starts("CHF")) ++counts_.motion_blocks;
    else if (starts("CP") || starts("CR") || starts("CT") || (starts("C") && f.size() > 1 && (f[1] == 'X' || f[1] == 'Y' || f[1] == 'Z' || f[1] == 'D'))) {
      ++counts_.motion_blocks;
      ++counts_.arcs;
    }
    return;
  }
  bool motion_word = false, group_word = false, axes = false;
  int mode = mode_;
  for (std::size_t i = 0; i < code.size(); ++i) {
    const char c = code[i];
    if (c == 'G' && i + 1 < code.size() && digit(code[i + 1])) {
      std::size_t j = i + 1;
      int n = 0;
      while (j < code.size() && digit(code[j])) n = n * 10 + (code[j++] - '0');
      const bool fraction = j < code.size() && code[j] == '.';
      if (!fraction && n <= 3) {
        motion_word = true;
        mode = n;
      } else if (n == 33 || n == 38 || n == 73 || n == 76 || n == 74 || (n >= 80 && n <= 89)) {
        group_word = true;
        mode = n == 80 ? -1 : 4;
      } else if (n == 4 || n == 10 || n == 28 || n == 30 || n == 52 || n == 53 || n == 92 || n == 65) {
        group_word = true;  // non-modal: the axis words are its own
      }
      i = j - 1;
    } else if ((c == 'X' || c == 'Y' || c == 'Z' || c == 'A' || c == 'B' || c == 'C' || c == 'U' || c == 'V' ||
                c == 'W') &&
               i + 1 < code.size() &&
               (digit(code[i + 1]) || code[i + 1] == '-' || code[i + 1] == '+' || code[i + 1] == '.' ||
                code[i + 1] == '=' || code[i + 1] == '[' || code[i + 1] == '#')) {
      // An axis word (not part of a longer name like CYCLE81 or MSG).
      if (i == 0 || !std::isalpha(static_cast<unsigned char>(code[i - 1]))) axes = true;
    }
  }
  mode_ = mode;
  if (motion_word || (axes && !group_word && mode >= 0 && mode <= 3)) {
    ++counts_.motion_blocks;
    if (mode == 2 || mode == 3) ++counts_.arcs;
  }
}

BlockCounts count_blocks(std::string_view text, bool heidenhain) {
  BlockCounter counter(heidenhain);
  counter.text(text);
  return counter.finish();
}

}  // namespace ncbridge::toolpath_optimizer
