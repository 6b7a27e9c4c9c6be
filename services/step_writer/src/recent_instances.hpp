#pragma once
// A fixed-size memory of value instances written recently (points, directions, placements,
// circles), by their exact value: a value written again while still remembered refers to the
// first instance instead of repeating it. Direct-mapped (a new value replaces the one in its
// slot), so memory stays flat however long the file, and what is shared depends only on the
// sequence of values: the same project always gives the same file.
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "ncbridge/step_writer/part21_value.hpp"

namespace ncbridge::step_writer::part21 {

template <std::size_t N>
class RecentInstances {
 public:
  using Key = std::array<std::uint64_t, N>;

  explicit RecentInstances(unsigned slot_bits) : mask_((std::size_t{1} << slot_bits) - 1), slots_(mask_ + 1) {}

  // The instance remembered for `key`, or 0.
  InstanceId find(const Key& key) const {
    const Slot& s = slots_[index(key)];
    for (std::size_t i = 0; i < N; ++i) {  // not std::array's ==, which calls memcmp
      if (s.key[i] != key[i]) return 0;
    }
    return s.id;
  }
  void remember(const Key& key, InstanceId id) { slots_[index(key)] = Slot{key, id}; }

  // Exact bits of a real: 0. and -0. are different values in a file.
  static std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

 private:
  struct Slot {
    Key key{};
    InstanceId id = 0;
  };
  std::size_t index(const Key& key) const {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::uint64_t w : key) {
      h ^= w;
      h *= 0xFF51AFD7ED558CCDull;
      h ^= h >> 32;
    }
    return static_cast<std::size_t>(h) & mask_;
  }

  std::size_t mask_;
  std::vector<Slot> slots_;
};

}  // namespace ncbridge::step_writer::part21
