#pragma once
// Program text read line by line, with seeking back to a remembered line start (loops and
// subroutine calls re-read their lines, as LinuxCNC does); memory stays flat in program length.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace ncbridge::interpreter {

class TextSource {
 public:
  virtual ~TextSource() = default;
  // The next line without its terminator (\n, \r\n); false at the end. The view stays valid
  // until the next call.
  virtual bool next_line(std::string_view& line) = 0;
  // Byte offset of the next line to be read.
  virtual std::uint64_t tell() const = 0;
  virtual void seek(std::uint64_t offset) = 0;
};

class MemoryTextSource final : public TextSource {
 public:
  explicit MemoryTextSource(std::string_view text) : text_(text) {}
  bool next_line(std::string_view& line) override;
  std::uint64_t tell() const override { return position_; }
  void seek(std::uint64_t offset) override { position_ = offset; }

 private:
  std::string_view text_;
  std::uint64_t position_ = 0;
};

// Throws std::system_error-free InputError when the file cannot be opened (see open_text_file).
class FileTextSource final : public TextSource {
 public:
  FileTextSource(std::FILE* file) : file_(file) { buffer_.resize(1 << 16); }
  ~FileTextSource() override;
  FileTextSource(const FileTextSource&) = delete;
  FileTextSource& operator=(const FileTextSource&) = delete;
  bool next_line(std::string_view& line) override;
  std::uint64_t tell() const override { return buffer_offset_ + begin_; }
  void seek(std::uint64_t offset) override;

 private:
  bool refill();
  std::FILE* file_;
  std::vector<char> buffer_;
  std::uint64_t buffer_offset_ = 0;  // file offset of buffer_[0]
  std::size_t begin_ = 0, end_ = 0;  // unread bytes are buffer_[begin_, end_)
  bool eof_ = false;
};

// nullptr when the file cannot be opened.
std::unique_ptr<TextSource> open_text_file(const std::filesystem::path& path);

}  // namespace ncbridge::interpreter
