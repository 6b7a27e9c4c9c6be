#include "text_source.hpp"

#include <cstring>

namespace ncbridge::interpreter {

namespace {
std::string_view strip_cr(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}
}  // namespace

bool MemoryTextSource::next_line(std::string_view& line) {
  if (position_ >= text_.size()) return false;
  auto start = static_cast<std::size_t>(position_);
  auto nl = text_.find('\n', start);
  if (nl == std::string_view::npos) {
    line = text_.substr(start);
    position_ = text_.size();
  } else {
    line = text_.substr(start, nl - start);
    position_ = nl + 1;
  }
  line = strip_cr(line);
  return true;
}

FileTextSource::~FileTextSource() { std::fclose(file_); }

bool FileTextSource::refill() {
  if (eof_) return false;
  if (begin_ > 0) {
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    buffer_offset_ += begin_;
    end_ -= begin_;
    begin_ = 0;
  }
  if (end_ == buffer_.size()) buffer_.resize(buffer_.size() * 2);  // one very long line
  std::size_t got = std::fread(buffer_.data() + end_, 1, buffer_.size() - end_, file_);
  if (got == 0) eof_ = true;
  end_ += got;
  return got > 0;
}

bool FileTextSource::next_line(std::string_view& line) {
  std::size_t scan_from = begin_;
  for (;;) {
    const char* base = buffer_.data();
    const void* nl = scan_from < end_ ? std::memchr(base + scan_from, '\n', end_ - scan_from) : nullptr;
    if (nl != nullptr) {
      auto pos = static_cast<std::size_t>(static_cast<const char*>(nl) - base);
      line = strip_cr(std::string_view(base + begin_, pos - begin_));
      begin_ = pos + 1;
      return true;
    }
    std::size_t scanned = end_ - begin_;
    if (!refill()) {
      if (begin_ == end_) return false;
      line = strip_cr(std::string_view(buffer_.data() + begin_, end_ - begin_));
      begin_ = end_;
      return true;
    }
    scan_from = begin_ + scanned;
  }
}

void FileTextSource::seek(std::uint64_t offset) {
  if (offset >= buffer_offset_ && offset <= buffer_offset_ + end_) {
    begin_ = static_cast<std::size_t>(offset - buffer_offset_);
    return;
  }
  std::fseek(file_, static_cast<long>(offset), SEEK_SET);
  buffer_offset_ = offset;
  begin_ = end_ = 0;
  eof_ = false;
}

std::unique_ptr<TextSource> open_text_file(const std::filesystem::path& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return nullptr;
  return std::make_unique<FileTextSource>(f);
}

}  // namespace ncbridge::interpreter
