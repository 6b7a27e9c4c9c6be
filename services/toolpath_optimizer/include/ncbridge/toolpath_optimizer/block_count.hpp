#pragma once
// Commands and motion blocks of a CNC program's text, counted as ANCHOR.md counts them (the
// figures `optimize` reports in and out): a command is a line with something besides a comment;
// a motion block is a line with a G0..G3 word (G00..G03 too), or with axis words and no G word
// of its own group or of the non-modal group (G4, G10, G28, G30, G52, G53, G92...) while G0..G3
// is the modal motion. Heidenhain conversational: L, LP, C, CP, CR, CT, RND, CHF blocks.
#include <cstdint>
#include <string>
#include <string_view>

namespace ncbridge::toolpath_optimizer {

struct BlockCounts {
  std::uint64_t bytes = 0, lines = 0, commands = 0, motion_blocks = 0, arcs = 0;
};

class BlockCounter {
 public:
  explicit BlockCounter(bool heidenhain = false) : heidenhain_(heidenhain) {}
  void text(std::string_view piece);  // any piece; lines may be split across pieces
  const BlockCounts& finish();
  const BlockCounts& counts() const { return counts_; }

 private:
  void line(std::string_view line);
  bool heidenhain_;
  int mode_ = -1;  // 0..3 for G0..G3, 4 for any other motion (G33, G38, G73, G8x ...), -1 none
  std::string pending_;
  BlockCounts counts_;
};

BlockCounts count_blocks(std::string_view text, bool heidenhain = false);

}  // namespace ncbridge::toolpath_optimizer
