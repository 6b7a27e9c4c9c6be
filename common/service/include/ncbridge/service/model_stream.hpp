#pragma once
// How a job's ISO 14649 model is laid out on the ncbridge/workingsteps topic (CC1, by the
// cc1_builder) and the ncbridge/features topic (what the step writer writes: CC2 from the
// feature_recognizer, or the CC1 model passed through): proto StepncModel samples (ncbridge/wire/
// workingsteps.hpp) whose `model` bytes are the parts of common/stepnc_codec/project_stream.hpp:
//   seq 0     kind kModelShell  the project's shell, with the job's level, requested level and
//                               output name;
//   seq 1..n  kind kModelChunk  the next workplan elements with the features and operations they
//                               are the first to name (about 1 MB each), the last one marked.
// A reader decodes each chunk as it comes. An element is never split: one larger than a chunk
// (a single workingstep of a huge toolpath) is a chunk of its own.
// A CC1 job's model goes to the step writer while it is built (the shell is known at the end):
//   seq 0     kind kModelStreamHead  the job's level, requested level and output name, no model;
//   seq 1..n  kind kModelElements    element chunks (stepnc_codec::ElementChunker, ~1 MB each);
//   seq n+1   kind kModelShell       the finished project's shell, marked last.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "ncbridge/bus/envelope.hpp"
#include "ncbridge/service/stage_runner.hpp"
#include "ncbridge/stepnc/project.hpp"
#include "ncbridge/stepnc_codec/project_stream.hpp"
#include "ncbridge/wire/workingsteps.hpp"

namespace ncbridge::service {

inline constexpr std::uint32_t kModelShell = 1;
inline constexpr std::uint32_t kModelChunk = 2;
inline constexpr std::uint32_t kModelStreamHead = 3;
inline constexpr std::uint32_t kModelElements = 4;
inline constexpr std::size_t kModelChunkBytes = std::size_t{1} << 20;

// What the shell sample says besides the model.
struct ModelHeader {
  wire::ModelLevel level = wire::ModelLevel::Cc1;
  wire::ModelLevel requested = wire::ModelLevel::Cc1;
  std::string output_name;
};

// Publishes `project` as the job's model stream (shell, then chunks; the last marked) on `topic`
// (workingsteps or features).
void publish_model(JobContext& context, bus::Topic topic, const ModelHeader& header, const stepnc::Project& project);

// Publishes a model element by element as a builder finishes them (the streamed layout above).
class ElementPublisher {
 public:
  ElementPublisher(JobContext& context, bus::Topic topic, ModelHeader header);
  void element(const stepnc::Project& project, const stepnc::Executable& element);
  // The rest of the elements, then `project`'s shell (the finished project, without elements).
  void finish(const stepnc::Project& project);

 private:
  void publish(std::uint32_t kind, bool last, std::string model);
  JobContext& context_;
  bus::Topic topic_;
  ModelHeader header_;
  std::uint64_t seq_ = 0;
  stepnc_codec::ElementChunker chunker_;
};

// Checks that a sample is part `kind` of this job's model (seq as the envelope's).
wire::StepncModel read_model_part(const std::string& job_id, const bus::Envelope& sample, std::uint32_t kind);

// Reads a job's model stream, sample by sample (in seq order), decoding each chunk as it comes.
// Throws InputError for a sample that is not the expected part of this job's model.
class ModelReceiver {
 public:
  explicit ModelReceiver(std::string job_id) : job_id_(std::move(job_id)) {}
  void sample(const bus::Envelope& sample);
  // Set once the shell came.
  const std::optional<ModelHeader>& header() const { return header_; }
  stepnc::Project take() { return joiner_.take(); }

  // Checks that a sample is the shell of this job's model and returns its header, without
  // decoding the model (a stage that passes the stream on).
  static ModelHeader read_header(const std::string& job_id, const bus::Envelope& shell);

 private:
  std::string job_id_;
  std::optional<ModelHeader> header_;
  stepnc_codec::ProjectJoiner joiner_;
};

}  // namespace ncbridge::service
