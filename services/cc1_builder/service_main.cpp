// ncbridge-cc1-builder: the cc1_builder stage as a DDS service. A job's canonical stream
// (context, then batches: ncbridge/service/canonical_stream.hpp) is fed to the builder batch by
// batch as it arrives, while the interpreter is still at work; the finished CC1 model is
// published as a model stream (ncbridge/service/model_stream.hpp) on the workingsteps topic for
// the feature_recognizer when the job asks for CC2. A CC1 job skips the recognizer: its workplan
// elements go to the step writer on the features topic in chunks as the builder finishes them,
// the project's shell at the end.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <memory>
#include <string>

#include "ncbridge/bus/topics.hpp"
#include "ncbridge/canonical/proto_codec.hpp"
#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/service/canonical_stream.hpp"
#include "ncbridge/service/model_stream.hpp"
#include "ncbridge/service/service_options.hpp"
#include "ncbridge/wire/job.hpp"

namespace {

using namespace ncbridge;

class ElementsOut final : public cc1_builder::WorkplanSink {
 public:
  explicit ElementsOut(service::ElementPublisher& publisher) : publisher_(publisher) {}
  void element(const stepnc::Project& project, const stepnc::Executable& element) override {
    publisher_.element(project, element);
  }

 private:
  service::ElementPublisher& publisher_;
};

class Cc1Stream final : public service::JobStream {
 public:
  explicit Cc1Stream(service::JobContext& context) : context_(context) {}

  void sample(bus::Envelope sample) override {
    if (!builder_) {
      if (sample.kind != service::kJobContext)
        throw InputError({"<canonical stream>", 0, 0}, "the stream does not start with the job's context");
      const wire::Job job = wire::decode_job(sample.payload);
      cc1_builder::Options options;
      options.tools = setup::ToolList(job.tools);
      options.stock = job.stock;
      header_.requested = job.level == wire::ConformanceClass::Cc2 ? wire::ModelLevel::Cc2 : wire::ModelLevel::Cc1;
      header_.output_name = job.output_name.empty() ? context_.job_id() + ".stp" : job.output_name;
      if (header_.requested == wire::ModelLevel::Cc1) {
        publisher_ = std::make_unique<service::ElementPublisher>(context_, bus::Topic::Features, header_);
        elements_ = std::make_unique<ElementsOut>(*publisher_);
      }
      builder_ = std::make_unique<cc1_builder::Cc1Builder>(options, elements_.get());
      return;
    }
    if (sample.kind != service::kCanonicalBatch)
      throw InputError({"<canonical stream>", 0, 0}, "sample " + std::to_string(sample.seq) + " is not a canonical batch");
    const canonical::DecodedBatch batch = canonical::decode_batch(sample.payload);
    if (batch.job_id != context_.job_id())
      throw InputError({"<canonical batch>", 0, 0},
                       "a batch of job \"" + batch.job_id + "\" in job \"" + context_.job_id() + "\"");
    canonical::replay(batch, *builder_);
  }

  void finish() override {
    if (!builder_) throw InputError({"<canonical stream>", 0, 0}, "the stream has no job context");
    builder_->end();
    for (const auto& w : builder_->warnings())
      spdlog::warn("job {}: {}: {}", context_.job_id(), w.where.to_string(), w.message);
    if (publisher_) publisher_->finish(builder_->take_project());
    else service::publish_model(context_, bus::Topic::Workingsteps, header_, builder_->take_project());
  }

 private:
  service::JobContext& context_;
  service::ModelHeader header_;
  std::unique_ptr<service::ElementPublisher> publisher_;  // a CC1 job's elements, as they are finished
  std::unique_ptr<ElementsOut> elements_;
  std::unique_ptr<cc1_builder::Cc1Builder> builder_;
};

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
    spec.other_outputs = {bus::Topic::Features};
    spec.open = [](const service::JobKey&, service::JobContext& context) -> std::unique_ptr<service::JobStream> {
      return std::make_unique<Cc1Stream>(context);
    };
    return spec;
  });
}
