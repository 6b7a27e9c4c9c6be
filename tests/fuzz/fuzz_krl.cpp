// libFuzzer target: the reader of the KRL subset `ncbridge optimize --to krl` writes
// (read_krl_text). Input must be read or refused with an InputError, never crash.
#include <cstdint>
#include <string_view>

#include "ncbridge/common/error.hpp"
#include "ncbridge/toolpath_optimizer/krl.hpp"

namespace opt = ncbridge::toolpath_optimizer;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  opt::ElementCollector sink;
  try {
    opt::read_krl_text(input, "fuzz.src", sink);
  } catch (const ncbridge::InputError&) {
  }
  return 0;
}
