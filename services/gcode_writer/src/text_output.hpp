#pragma once
// Program text on its way out: collected in a buffer that goes to the writer's output in
// pieces of about 64 KiB, so memory does not grow with the program.
#include <functional>
#include <string>
#include <string_view>

namespace ncbridge::gcode_writer {

class TextOutput {
 public:
  using Output = std::function<void(std::string_view)>;
  explicit TextOutput(Output output) : output_(std::move(output)) { buffer_.reserve(kPiece + 4096); }

  // The line being made: append to it, then end_line().
  std::string& line() { return buffer_; }
  void end_line() {
    buffer_.push_back('\n');
    if (buffer_.size() >= kPiece) flush();
  }
  void flush() {
    if (!buffer_.empty()) output_(buffer_);
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kPiece = 64 * 1024;
  Output output_;
  std::string buffer_;
};

}  // namespace ncbridge::gcode_writer
