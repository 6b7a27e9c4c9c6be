#pragma once
// A written ISO 10303-21 file, or one piece of it, on the ncbridge/part21 topic
// (proto/part21.proto), and its codec.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace ncbridge::wire {

enum class Part21Level : std::uint8_t { Cc1, Cc2 };

struct Part21File {
  std::string job_id;
  Part21Level level = Part21Level::Cc1;
  std::string file_name;
  std::string content;
  std::array<std::uint8_t, 32> sha256{};   // digest of content, computed by the writer
  std::uint64_t seq = 0;                   // piece number
  bool more = false;                       // pieces follow this one
  friend bool operator==(const Part21File&, const Part21File&) = default;
};

std::string encode_part21(const Part21File& file);
Part21File decode_part21(std::string_view bytes);  // throws InputError on malformed bytes

}  // namespace ncbridge::wire
