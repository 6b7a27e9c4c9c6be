#pragma once
// SHA-256 of a file's bytes (the digest the part21 topic carries beside the content).
#include <array>
#include <cstdint>
#include <string_view>

namespace ncbridge::service {

std::array<std::uint8_t, 32> sha256(std::string_view bytes);

}  // namespace ncbridge::service
