#pragma once
// Printer G-code out: the inverse of the printer front-end (printer_reader.hpp). Lines that came
// through unchanged are written byte for byte; a made motion is written in the style of the
// lines it replaced: `G1 X.. Y.. E..` or `G2`/`G3` with I J (K) centre offsets, the same decimals
// (one more for the centre), E absolute or relative as the file had it, F when the first line it
// replaced had one, the same line ending. Printer G-code has no loop: a Loop element is an error.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "ncbridge/toolpath_optimizer/toolpath.hpp"

namespace ncbridge::toolpath_optimizer {

class PrinterWriter final : public ElementSink {
 public:
  // `centre_decimals` -1: one more than the motion's coordinates.
  explicit PrinterWriter(std::function<void(std::string_view)> out, int centre_decimals = -1);
  ~PrinterWriter() override;
  void element(Element&& e) override;
  void end() override;

  std::uint64_t lines() const { return lines_; }
  std::uint64_t commands() const { return commands_; }
  std::uint64_t motion_blocks() const { return motion_blocks_; }
  std::uint64_t bytes() const { return bytes_; }

  // The text of a made motion (without line ending), for tests and the KRL comments.
  static void format_motion(const Motion& m, std::string& out, int centre_decimals = -1);

 private:
  void write(std::string_view text, bool command);
  void flush();
  std::function<void(std::string_view)> out_;
  int centre_decimals_;
  std::string buffer_;
  std::uint64_t lines_ = 0, commands_ = 0, motion_blocks_ = 0, bytes_ = 0;
};

}  // namespace ncbridge::toolpath_optimizer
