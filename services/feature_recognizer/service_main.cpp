// ncbridge-feature-recognizer: the feature_recognizer stage as a DDS service, between the
// workingsteps and features topics.
//
// What it does today: the recogniser's API still ends at its own feature list (recognizer.hpp);
// the mapping of recognised features into the CC2 model (stepnc::Project) is not there yet. So
// every workplan passes through as CC1 (level CC1 on the features topic). When a job asks for
// CC2, the service runs the recogniser on the CC1 model and reports what it found in the log,
// but the file written is still CC1.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <string>

#include "ncbridge/bus/topics.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/feature_recognizer/cc1_input.hpp"
#include "ncbridge/feature_recognizer/recognizer.hpp"
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
  if (model.requested == wire::ModelLevel::Cc2) {
    if (const auto stock = feature_recognizer::stock_from_cc1(project)) {
      const auto features = feature_recognizer::recognize(feature_recognizer::workingsteps_from_cc1(project), *stock);
      spdlog::info("job {}: {} features recognised; the CC2 model mapping is not bound yet, writing CC1",
                   input.job_id, features.size());
    } else {
      spdlog::warn("job {}: CC2 asked for but the model has no rawpiece (stock); writing CC1", input.job_id);
    }
  }
  context.output().write(input.job_id, "", 0, 0, true, wire::encode_stepnc_model(model));
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
