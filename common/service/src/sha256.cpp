#include "ncbridge/service/sha256.hpp"

#include <openssl/sha.h>

namespace ncbridge::service {

std::array<std::uint8_t, 32> sha256(std::string_view bytes) {
  std::array<std::uint8_t, 32> digest{};
  SHA256(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), digest.data());
  return digest;
}

}  // namespace ncbridge::service
