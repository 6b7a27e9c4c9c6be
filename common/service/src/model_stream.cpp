#include "ncbridge/service/model_stream.hpp"

#include "ncbridge/common/error.hpp"

namespace ncbridge::service {
namespace {

const char* name_of(std::uint32_t kind) {
  switch (kind) {
    case kModelShell: return "shell";
    case kModelChunk: return "chunk";
    case kModelStreamHead: return "stream head";
    case kModelElements: return "element chunk";
    default: return "part";
  }
}

}  // namespace

wire::StepncModel read_model_part(const std::string& job_id, const bus::Envelope& sample, std::uint32_t kind) {
  if (sample.kind != kind)
    throw InputError({"<stepnc model>", 0, 0}, "sample " + std::to_string(sample.seq) + " of job \"" + job_id + "\" is not a model " +
                                                   name_of(kind));
  wire::StepncModel m = wire::decode_stepnc_model(sample.payload);
  if (m.job_id != job_id)
    throw InputError({"<stepnc model>", 0, 0}, "a model of job \"" + m.job_id + "\" in job \"" + job_id + "\"");
  if (m.seq != sample.seq)
    throw InputError({"<stepnc model>", 0, 0}, "model part " + std::to_string(m.seq) + " in sample " + std::to_string(sample.seq));
  return m;
}

ElementPublisher::ElementPublisher(JobContext& context, bus::Topic topic, ModelHeader header)
    : context_(context), topic_(topic), header_(std::move(header)) {
  publish(kModelStreamHead, false, {});
}

void ElementPublisher::element(const stepnc::Project& project, const stepnc::Executable& element) {
  chunker_.element(project, element);
  if (chunker_.bytes() >= kModelChunkBytes) publish(kModelElements, false, chunker_.take_chunk(project));
}

void ElementPublisher::finish(const stepnc::Project& project) {
  if (chunker_.elements() > 0) publish(kModelElements, false, chunker_.take_chunk(project));
  publish(kModelShell, true, stepnc_codec::split_project(project, kModelChunkBytes).shell);
}

void ElementPublisher::publish(std::uint32_t kind, bool last, std::string model) {
  wire::StepncModel m;
  m.job_id = context_.job_id();
  m.level = header_.level;
  m.requested = header_.requested;
  m.output_name = header_.output_name;
  m.seq = seq_;
  m.last = last;
  m.model = std::move(model);
  context_.publish_on(topic_, "", seq_, kind, last, wire::encode_stepnc_model(m));
  ++seq_;
}

void publish_model(JobContext& context, bus::Topic topic, const ModelHeader& header, const stepnc::Project& project) {
  const stepnc_codec::ProjectParts parts = stepnc_codec::split_project(project, kModelChunkBytes);
  wire::StepncModel m;
  m.job_id = context.job_id();
  m.level = header.level;
  m.requested = header.requested;
  m.output_name = header.output_name;
  m.seq = 0;
  m.last = false;
  m.model = parts.shell;
  context.publish_on(topic, "", 0, kModelShell, false, wire::encode_stepnc_model(m));
  for (std::size_t i = 0; i < parts.chunks.size(); ++i) {
    m.seq = i + 1;
    m.last = i + 1 == parts.chunks.size();
    m.model = parts.chunks[i];
    context.publish_on(topic, "", m.seq, kModelChunk, m.last, wire::encode_stepnc_model(m));
  }
}

ModelHeader ModelReceiver::read_header(const std::string& job_id, const bus::Envelope& shell) {
  const wire::StepncModel m = read_model_part(job_id, shell, kModelShell);
  return {m.level, m.requested, m.output_name};
}

void ModelReceiver::sample(const bus::Envelope& sample) {
  if (!header_) {
    const wire::StepncModel m = read_model_part(job_id_, sample, kModelShell);
    joiner_.shell(m.model);
    header_ = ModelHeader{m.level, m.requested, m.output_name};
    return;
  }
  joiner_.chunk(read_model_part(job_id_, sample, kModelChunk).model);
}

}  // namespace ncbridge::service
