// ncbridge-feature-recognizer: the feature_recognizer stage as a DDS service, between the
// workingsteps and features topics. A job that asks for CC2 gets its features recognised in
// the CC1 model and the CC2 project built from them, with the same library calls as
// `ncbridge convert --level cc2` (cli/src/cc2_output.cpp: the stock is the model's rawpiece);
// a CC1 job's model passes through.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <string>

#include "ncbridge/bus/topics.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/feature_recognizer/cc1_input.hpp"
#include "ncbridge/feature_recognizer/recognizer.hpp"
#include "ncbridge/feature_recognizer/to_stepnc.hpp"
#include "ncbridge/service/service_options.hpp"
#include "ncbridge/stepnc_codec/project_codec.hpp"
#include "ncbridge/wire/workingsteps.hpp"

namespace {

using namespace ncbridge;

void recognize(const service::JobInput& input, service::JobContext& context) {
  const wire::StepncModel model = wire::decode_stepnc_model(input.payloads.back());
  if (model.job_id != input.job_id)
    throw InputError({"<stepnc model>", 0, 0}, "a model of job \"" + model.job_id + "\" in job \"" + input.job_id + "\"");
  const stepnc::Project project = stepnc_codec::decode_project(model.model);  // rejects a bad model here
  if (model.requested != wire::ModelLevel::Cc2) {
    context.output().write(input.job_id, "", 0, 0, true, wire::encode_stepnc_model(model));
    return;
  }
  const auto stock = feature_recognizer::stock_from_cc1(project);
  if (!stock) throw InputError({"<stepnc model>", 0, 0}, "CC2 needs the stock, and the job's model has no rawpiece");
  const auto features = feature_recognizer::recognize(feature_recognizer::workingsteps_from_cc1(project), *stock);
  auto cc2 = feature_recognizer::cc2_from_cc1(project, features);
  for (const std::string& w : cc2.warnings) spdlog::warn("job {}: {}", input.job_id, w);
  spdlog::info("job {}: {} features recognised", input.job_id, features.size());
  wire::StepncModel out = model;
  out.level = wire::ModelLevel::Cc2;
  out.model = stepnc_codec::encode_project(cc2.project);
  context.output().write(input.job_id, "", 0, 0, true, wire::encode_stepnc_model(out));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ncbridge-feature-recognizer: CC1 workingsteps -> features (DDS service)",
               "ncbridge-feature-recognizer"};
  service::ServiceOptions options;
  service::add_service_options(app, options);
  return service::run_service(argc, argv, app, options, [] {
    service::StageSpec spec;
    spec.stage = std::string(bus::kStageFeatureRecognizer);
    spec.inputs = {{bus::Topic::Workingsteps, false}};
    spec.output = bus::Topic::Features;
    spec.run = recognize;
    return spec;
  });
}
