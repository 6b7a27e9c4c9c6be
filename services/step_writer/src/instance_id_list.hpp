#pragma once
// A list of instance ids kept as the differences between neighbours in variable-length bytes
// (7 bits a byte): the ids of a streamed workplan's elements rise by a few dozen each, so the
// list costs about a byte per element where a vector would cost eight.
#include <cstdint>
#include <vector>

#include "ncbridge/step_writer/part21_value.hpp"

namespace ncbridge::step_writer::part21 {

class InstanceIdList {
 public:
  void push_back(InstanceId id) {
    // Zig-zag, so that an id below its predecessor (allowed, if unusual) still fits.
    const std::int64_t delta = static_cast<std::int64_t>(id - last_);
    std::uint64_t v = (static_cast<std::uint64_t>(delta) << 1) ^ static_cast<std::uint64_t>(delta >> 63);
    while (v >= 0x80) {
      bytes_.push_back(static_cast<std::uint8_t>(v | 0x80));
      v >>= 7;
    }
    bytes_.push_back(static_cast<std::uint8_t>(v));
    last_ = id;
    ++size_;
  }

  template <class F>
  void for_each(F&& f) const {
    InstanceId id = 0;
    std::uint64_t v = 0;
    int shift = 0;
    for (const std::uint8_t b : bytes_) {
      v |= static_cast<std::uint64_t>(b & 0x7F) << shift;
      shift += 7;
      if (b & 0x80) continue;
      id += static_cast<InstanceId>((v >> 1) ^ (~(v & 1) + 1));
      f(id);
      v = 0;
      shift = 0;
    }
  }

  std::size_t size() const { return size_; }

 private:
  std::vector<std::uint8_t> bytes_;
  InstanceId last_ = 0;
  std::size_t size_ = 0;
};

}  // namespace ncbridge::step_writer::part21
