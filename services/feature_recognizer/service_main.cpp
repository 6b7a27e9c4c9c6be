// ncbridge-feature-recognizer: the feature_recognizer stage as a DDS service, between the
// workingsteps and features topics (model streams: ncbridge/service/model_stream.hpp). A job
// that asks for CC2 has its model decoded chunk by chunk as it arrives, then its features
// recognised and the CC2 project built from them, with the same library calls as
// `ncbridge convert --level cc2` (cli/src/cc2_output.cpp: the stock is the model's rawpiece).
// CC1 jobs normally skip this stage (the cc1_builder publishes their model on the features
// topic); a CC1 model that comes here anyway is passed on sample by sample as it comes, not
// decoded (the step writer checks it).
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <memory>
#include <optional>
#include <string>

#include "ncbridge/bus/topics.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/feature_recognizer/cc1_input.hpp"
#include "ncbridge/feature_recognizer/recognizer.hpp"
#include "ncbridge/feature_recognizer/to_stepnc.hpp"
#include "ncbridge/service/model_stream.hpp"
#include "ncbridge/service/service_options.hpp"

namespace {

using namespace ncbridge;

class RecognizerStream final : public service::JobStream {
 public:
  explicit RecognizerStream(service::JobContext& context) : context_(context), model_(context.job_id()) {}

  void sample(bus::Envelope sample) override {
    if (!pass_through_) {  // the shell: is this a CC2 job?
      pass_through_ = service::ModelReceiver::read_header(context_.job_id(), sample).requested != wire::ModelLevel::Cc2;
    }
    if (*pass_through_) {
      context_.publish(sample.subkey, sample.seq, sample.kind, sample.last, sample.payload);
    } else {
      model_.sample(sample);
    }
  }

  void finish() override {
    if (pass_through_.value_or(true)) return;
    const stepnc::Project project = model_.take();
    const auto stock = feature_recognizer::stock_from_cc1(project);
    if (!stock) throw InputError({"<stepnc model>", 0, 0}, "CC2 needs the stock, and the job's model has no rawpiece");
    feature_recognizer::Options options;
    options.checkpoint = [this] { context_.check_time(); };  // the worker's job time limit
    const auto features = feature_recognizer::recognize(feature_recognizer::workingsteps_from_cc1(project), *stock, options);
    const auto cc2 = feature_recognizer::cc2_from_cc1(project, features);
    for (const std::string& w : cc2.warnings) spdlog::warn("job {}: {}", context_.job_id(), w);
    spdlog::info("job {}: {} features recognised", context_.job_id(), features.size());
    service::ModelHeader header = *model_.header();
    header.level = wire::ModelLevel::Cc2;
    service::publish_model(context_, bus::Topic::Features, header, cc2.project);
  }

 private:
  service::JobContext& context_;
  service::ModelReceiver model_;
  std::optional<bool> pass_through_;
};

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
    spec.open = [](const service::JobKey&, service::JobContext& context) -> std::unique_ptr<service::JobStream> {
      return std::make_unique<RecognizerStream>(context);
    };
    return spec;
  });
}
