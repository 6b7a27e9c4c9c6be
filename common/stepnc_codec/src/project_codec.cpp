#include "ncbridge/stepnc_codec/project_codec.hpp"

#include "model_fields.hpp"

namespace ncbridge::stepnc_codec {
namespace {
constexpr std::string_view kMagic = "NCBM";
}  // namespace

using detail::Decoder;
using detail::Encoder;
using detail::kVersion;

std::string encode_project(const stepnc::Project& project) {
  std::string out(kMagic);
  Encoder enc(out);
  enc(kVersion, project);
  return out;
}

stepnc::Project decode_project(std::string_view bytes) {
  Decoder dec(bytes);
  if (dec.take(std::min(bytes.size(), kMagic.size())) != kMagic) dec.fail("not an ncbridge model (magic)");
  std::uint32_t version = 0;
  dec(version);
  if (version != kVersion) dec.fail("model format version " + std::to_string(version) + ", expected " +
                                    std::to_string(kVersion));
  stepnc::Project project;
  dec(project);
  dec.expect_end();
  return project;
}

}  // namespace ncbridge::stepnc_codec
