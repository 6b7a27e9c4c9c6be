#pragma once
// One part (shell or chunk) of a job's ISO 14649 model on the ncbridge/workingsteps and
// ncbridge/features topics (proto/workingsteps.proto), and its codec. The model bytes are opaque
// here (common/stepnc_codec/project_stream.hpp makes and reads them).
#include <cstdint>
#include <string>
#include <string_view>

namespace ncbridge::wire {

enum class ModelLevel : std::uint8_t { Cc1, Cc2 };

struct StepncModel {
  std::string job_id;
  std::uint64_t seq = 0;
  bool last = true;
  ModelLevel level = ModelLevel::Cc1;
  ModelLevel requested = ModelLevel::Cc1;
  std::string output_name;
  std::string model;
  friend bool operator==(const StepncModel&, const StepncModel&) = default;
};

std::string encode_stepnc_model(const StepncModel& model);
StepncModel decode_stepnc_model(std::string_view bytes);  // throws InputError on malformed bytes

}  // namespace ncbridge::wire
