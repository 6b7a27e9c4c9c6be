#pragma once
// A dialect program read as a stream of lines. The label-and-jump dialects (Fanuc GOTO n,
// Siemens GOTOF/GOTOB, Heidenhain LBL) and subprogram calls address lines by number, so the
// front-ends see numbered lines; only the line being read is held. A jump seeks by file offset:
// to one of the last few lines read, or to the nearest checkpoint (the offset of every 256th
// line, 8 bytes per 256 lines) and reads forward from there. Memory stays flat in program
// length, as with the RS274 reader (text_source.hpp).
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "text_source.hpp"

namespace ncbridge::interpreter::lowering {

class ProgramText {
 public:
  std::string name;  // as the user named it, for messages

  ProgramText() = default;
  ProgramText(ProgramText&&) noexcept = default;
  ProgramText& operator=(ProgramText&&) noexcept = default;

  std::size_t size() const { return lines_; }
  // Line `index` (0-based) without its terminator; valid until the next call of line().
  std::string_view line(std::size_t index) const;

  static ProgramText from_text(std::string text, std::string name);
  // Throws InputError when the file cannot be read.
  static ProgramText from_file(const std::filesystem::path& path);

 private:
  static constexpr std::size_t kStride = 256;
  static constexpr std::size_t kRecent = 16;
  void index_lines();
  void read_next() const;

  std::unique_ptr<std::string> owned_;           // the text of from_text
  std::unique_ptr<TextSource> source_;
  std::vector<std::uint64_t> checkpoints_;       // offset of line k * kStride
  std::size_t lines_ = 0;
  // the reading position: the source is at the start of line next_
  mutable std::size_t next_ = 0;
  mutable std::string current_;
  mutable std::size_t current_index_ = static_cast<std::size_t>(-1);
  struct Recent {
    std::size_t index = static_cast<std::size_t>(-1);
    std::uint64_t offset = 0;
  };
  mutable std::array<Recent, kRecent> recent_{};  // start offsets of the lines read last
};

}  // namespace ncbridge::interpreter::lowering
