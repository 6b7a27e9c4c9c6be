#pragma once
// Every DDS topic of ncbridge, with what its two envelope keys mean (proto/envelope.idl).
#include <array>
#include <cstdint>
#include <string_view>

namespace ncbridge::bus {

enum class Topic : std::uint8_t {
  Programs,      // key = job_id,        subkey = ""         payload: proto Job
  Blocks,        // key = controller_id, subkey = run_id     payload: proto ExecutedBlock
  Canonical,     // key = job_id,        subkey = ""         payload: seq 0 proto Job (context), then CanonicalBatch
  // The two model topics carry proto StepncModel samples: seq 0 the model's shell, then chunks
  // of workplan elements with their features and operations (ncbridge/service/model_stream.hpp).
  Workingsteps,  // key = job_id,        subkey = ""         payload: the CC1 model of a CC2 job (to recognise)
  Features,      // key = job_id,        subkey = ""         payload: the model to write: CC2, or a CC1 job's CC1
  Part21,        // key = job_id,        subkey = "cc1"|"cc2" payload: proto Part21File
  Status,        // key = job_id,        subkey = stage      payload: proto JobStatus
  Workers,       // key = stage,         subkey = worker_id  payload: proto Worker
};

inline constexpr std::array<Topic, 8> kAllTopics{Topic::Programs, Topic::Blocks, Topic::Canonical,
                                                 Topic::Workingsteps, Topic::Features, Topic::Part21,
                                                 Topic::Status, Topic::Workers};

constexpr std::string_view topic_name(Topic topic) {
  switch (topic) {
    case Topic::Programs: return "ncbridge/programs";
    case Topic::Blocks: return "ncbridge/blocks";
    case Topic::Canonical: return "ncbridge/canonical";
    case Topic::Workingsteps: return "ncbridge/workingsteps";
    case Topic::Features: return "ncbridge/features";
    case Topic::Part21: return "ncbridge/part21";
    case Topic::Status: return "ncbridge/status";
    case Topic::Workers: return "ncbridge/workers";
  }
  return "";
}

// Stage names, as used in status subkeys and worker keys.
inline constexpr std::string_view kStageInterpreter = "interpreter";
inline constexpr std::string_view kStageCc1Builder = "cc1_builder";
inline constexpr std::string_view kStageFeatureRecognizer = "feature_recognizer";
inline constexpr std::string_view kStageStepWriter = "step_writer";
inline constexpr std::string_view kStageClient = "client";  // a JobWatch: "delivered"

}  // namespace ncbridge::bus
