#include "ncbridge/bus/routing.hpp"

#include <cstdio>

namespace ncbridge::bus {

std::optional<std::string_view> routed_to(Topic topic) {
  switch (topic) {
    case Topic::Programs: return kStageInterpreter;
    case Topic::Canonical: return kStageCc1Builder;
    case Topic::Workingsteps: return kStageFeatureRecognizer;
    case Topic::Features: return kStageStepWriter;
    default: return std::nullopt;
  }
}

std::string worker_partition(std::string_view stage, std::string_view worker_id) {
  std::string p = "ncbridge.to.";
  p += stage;
  p += '.';
  for (const char c : worker_id) {
    if (c == '*' || c == '?' || c == '%' || c == '\\') {
      char escaped[4];
      std::snprintf(escaped, sizeof escaped, "%%%02X", static_cast<unsigned char>(c));
      p += escaped;
    } else {
      p += c;
    }
  }
  return p;
}

}  // namespace ncbridge::bus
