// ncbridge-cc1-builder: the cc1_builder stage as a DDS service. A job's canonical stream
// (context, then batches: ncbridge/service/canonical_stream.hpp) becomes its CC1 model,
// published whole on the workingsteps topic.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <string>

#include "ncbridge/bus/topics.hpp"
#include "ncbridge/canonical/proto_codec.hpp"
#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/service/canonical_stream.hpp"
#include "ncbridge/service/service_options.hpp"
#include "ncbridge/stepnc_codec/project_codec.hpp"
#include "ncbridge/wire/job.hpp"
#include "ncbridge/wire/workingsteps.hpp"

namespace {

using namespace ncbridge;

void build(const service::JobInput& input, service::JobContext& context) {
  if (input.kinds.front() != service::kJobContext)
    throw InputError({"<canonical stream>", 0, 0}, "the stream does not start with the job's context");
  const wire::Job job = wire::decode_job(input.payloads.front());
  cc1_builder::Options options;
  options.tools = setup::ToolList(job.tools);
  options.stock = job.stock;
  cc1_builder::Cc1Builder builder(options);
  const double batches = static_cast<double>(input.payloads.size());
  for (std::size_t i = 1; i < input.payloads.size(); ++i) {
    if (input.kinds[i] != service::kCanonicalBatch)
      throw InputError({"<canonical stream>", 0, 0}, "sample " + std::to_string(i) + " is not a canonical batch");
    const canonical::DecodedBatch batch = canonical::decode_batch(input.payloads[i]);
    if (batch.job_id != input.job_id)
      throw InputError({"<canonical batch>", 0, 0}, "a batch of job \"" + batch.job_id + "\" in job \"" + input.job_id + "\"");
    canonical::replay(batch, builder);
    context.progress(static_cast<double>(i) / batches);
  }
  builder.end();
  for (const auto& w : builder.warnings()) spdlog::warn("job {}: {}: {}", input.job_id, w.where.to_string(), w.message);

  wire::StepncModel model;
  model.job_id = input.job_id;
  model.level = wire::ModelLevel::Cc1;
  model.requested = job.level == wire::ConformanceClass::Cc2 ? wire::ModelLevel::Cc2 : wire::ModelLevel::Cc1;
  model.output_name = job.output_name.empty() ? input.job_id + ".stp" : job.output_name;
  model.model = stepnc_codec::encode_project(builder.take_project());
  context.output().write(input.job_id, "", 0, 0, true, wire::encode_stepnc_model(model));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ncbridge-cc1-builder: canonical calls -> CC1 workingsteps (DDS service)", "ncbridge-cc1-builder"};
  service::ServiceOptions options;
  service::add_service_options(app, options);
  return service::run_service(argc, argv, app, options, [] {
    service::StageSpec spec;
    spec.stage = std::string(bus::kStageCc1Builder);
    spec.inputs = {{bus::Topic::Canonical, false}};
    spec.output = bus::Topic::Workingsteps;
    spec.run = build;
    return spec;
  });
}
