#include "lowering/program_text.hpp"

#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter::lowering {

ProgramText ProgramText::from_text(std::string text, std::string name) {
  ProgramText p;
  p.name = std::move(name);
  p.owned_ = std::make_unique<std::string>(std::move(text));
  p.source_ = std::make_unique<MemoryTextSource>(*p.owned_);
  p.index_lines();
  return p;
}

ProgramText ProgramText::from_file(const std::filesystem::path& path) {
  ProgramText p;
  p.name = path.string();
  p.source_ = open_text_file(path);
  if (!p.source_) throw InputError({path.string(), 0, 0}, "cannot open program file");
  p.index_lines();
  return p;
}

void ProgramText::index_lines() {
  std::string_view l;
  for (;;) {
    const std::uint64_t offset = source_->tell();
    if (!source_->next_line(l)) break;
    if (lines_ % kStride == 0) checkpoints_.push_back(offset);
    ++lines_;
  }
  source_->seek(0);
  next_ = 0;
}

void ProgramText::read_next() const {
  const std::uint64_t offset = source_->tell();
  std::string_view l;
  if (!source_->next_line(l)) l = {};
  current_.assign(l.data(), l.size());
  current_index_ = next_;
  recent_[next_ % kRecent] = Recent{next_, offset};
  ++next_;
}

std::string_view ProgramText::line(std::size_t index) const {
  if (index == current_index_) return current_;
  if (index >= lines_) return {};
  if (index != next_) {
    const Recent& r = recent_[index % kRecent];
    if (r.index == index) {
      source_->seek(r.offset);
      next_ = index;
    } else {
      const std::size_t k = index / kStride;
      // reading on from here is shorter than from the checkpoint
      if (!(index > next_ && next_ >= k * kStride)) {
        source_->seek(checkpoints_[k]);
        next_ = k * kStride;
      }
      while (next_ < index) read_next();
    }
  }
  read_next();
  return current_;
}

}  // namespace ncbridge::interpreter::lowering
