// ncbridge-step-writer: the step_writer stage as a DDS service. A job's model stream from the
// features topic (ncbridge/service/model_stream.hpp) is decoded chunk by chunk as it arrives:
// a CC1 model streamed by the cc1_builder is written element by element as it comes
// (StepncStreamWriter), a whole model once it is complete, with the same library calls (and so
// the same bytes) as `ncbridge convert`: into --output-dir (atomically), and onto the part21 topic in pieces of
// about 1 MB as it is written, each with its digest.
// Results stay on the part21 topic for late readers within the retention policy (--retain-*).
#include <CLI/CLI.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "ncbridge/bus/topics.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/service/model_stream.hpp"
#include "ncbridge/service/service_options.hpp"
#include "ncbridge/service/sha256.hpp"
#include "ncbridge/step_writer/atomic_file.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/step_writer/stepnc_stream_writer.hpp"
#include "ncbridge/stepnc_codec/project_stream.hpp"
#include "ncbridge/wire/part21.hpp"

namespace {

using namespace ncbridge;

// The output name comes from the job's submitter: a bare file name, nothing that leaves the
// output directory.
void check_output_name(const std::string& name) {
  const std::filesystem::path p(name);
  if (name.empty() || p.filename() != p || name == "." || name == "..")
    throw InputError({"<stepnc model>", 0, 0}, "output name \"" + name + "\" is not a plain file name");
}

// A file is published in pieces of about this size (proto/part21.proto).
constexpr std::size_t kPieceBytes = std::size_t{1} << 20;

// The file's text, as it is written: onto the part21 topic in pieces and into --output-dir.
class PieceOut {
 public:
  PieceOut(service::JobContext& context, const std::filesystem::path& output_dir, const service::ModelHeader& header)
      : context_(context) {
    check_output_name(header.output_name);
    piece_.job_id = context.job_id();
    piece_.level = header.level == wire::ModelLevel::Cc2 ? wire::Part21Level::Cc2 : wire::Part21Level::Cc1;
    piece_.file_name = header.output_name;
    subkey_ = piece_.level == wire::Part21Level::Cc2 ? "cc2" : "cc1";
    if (!output_dir.empty()) file_.emplace(output_dir / piece_.file_name);
  }
  void write(std::string_view bytes) {
    piece_.content.append(bytes);
    if (piece_.content.size() >= kPieceBytes) publish(false);
  }
  void finish() {
    publish(true);
    if (file_) file_->commit();
  }

 private:
  void publish(bool last) {
    piece_.sha256 = service::sha256(piece_.content);
    piece_.more = !last;
    context_.publish(subkey_, piece_.seq, 0, last, wire::encode_part21(piece_));
    if (file_) file_->write(piece_.content);
    piece_.content.clear();
    ++piece_.seq;
  }
  service::JobContext& context_;
  wire::Part21File piece_;
  std::string subkey_;
  std::optional<step_writer::AtomicFile> file_;
};

step_writer::StepncWriteOptions write_options(const service::ModelHeader& header) {
  step_writer::StepncWriteOptions options;
  options.file_name = header.output_name;
  if (header.level == wire::ModelLevel::Cc2) options.description = {"ISO 14649 CC2 program written by ncbridge"};  // as convert
  return options;
}

// A CC1 model streamed by the cc1_builder (model_stream.hpp): each element chunk is written as it
// comes, the setup, WORKPLAN and PROJECT once the shell came.
class StreamedCc1 {
 public:
  StreamedCc1(service::JobContext& context, const std::filesystem::path& output_dir, const service::ModelHeader& header)
      : out_(context, output_dir, header), writer_(write_options(header), [this](std::string_view bytes) { out_.write(bytes); }) {}
  void sample(const std::string& job_id, const bus::Envelope& sample) {
    if (shell_) throw InputError({"<stepnc model>", 0, 0}, "sample " + std::to_string(sample.seq) + " after the model's shell");
    if (sample.kind == service::kModelShell) {
      stepnc_codec::ProjectJoiner joiner;
      joiner.shell(service::read_model_part(job_id, sample, service::kModelShell).model);
      shell_ = joiner.take();
      return;
    }
    elements_.chunk(service::read_model_part(job_id, sample, service::kModelElements).model,
                    [this](const stepnc::Project& project, const stepnc::Executable& element) { writer_.element(project, element); });
  }
  void finish() {
    if (!shell_) throw InputError({"<stepnc model>", 0, 0}, "the streamed model ended without its shell");
    writer_.finish(*shell_);
    out_.finish();
  }

 private:
  PieceOut out_;
  step_writer::StepncStreamWriter writer_;
  stepnc_codec::ElementUnchunker elements_;
  std::optional<stepnc::Project> shell_;
};

class WriterStream final : public service::JobStream {
 public:
  WriterStream(service::JobContext& context, const std::filesystem::path& output_dir)
      : context_(context), output_dir_(output_dir), model_(context.job_id()) {}

  void sample(bus::Envelope sample) override {
    if (sample.seq == 0 && sample.kind == service::kModelStreamHead) {
      const wire::StepncModel head = service::read_model_part(context_.job_id(), sample, service::kModelStreamHead);
      if (head.level != wire::ModelLevel::Cc1)
        throw InputError({"<stepnc model>", 0, 0}, "a streamed model that is not CC1");
      streamed_ = std::make_unique<StreamedCc1>(context_, output_dir_, service::ModelHeader{head.level, head.requested, head.output_name});
      return;
    }
    if (streamed_) return streamed_->sample(context_.job_id(), sample);
    model_.sample(sample);
    if (model_.header() && sample.seq == 0) check_output_name(model_.header()->output_name);
  }

  void finish() override {
    if (streamed_) return streamed_->finish();
    const service::ModelHeader& header = *model_.header();
    const stepnc::Project project = model_.take();
    PieceOut out(context_, output_dir_, header);
    step_writer::write_stepnc(project, write_options(header), [&](std::string_view bytes) { out.write(bytes); });
    out.finish();
  }

 private:
  service::JobContext& context_;
  const std::filesystem::path& output_dir_;
  service::ModelReceiver model_;
  std::unique_ptr<StreamedCc1> streamed_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ncbridge-step-writer: models -> ISO 10303-21 files (DDS service)", "ncbridge-step-writer"};
  service::ServiceOptions options;
  service::add_service_options(app, options);
  std::string output_dir;
  app.add_option("--output-dir", output_dir, "Also write each file here (default: only the part21 topic)")
      ->check(CLI::ExistingDirectory);
  return service::run_service(argc, argv, app, options, [&] {
    service::StageSpec spec;
    spec.stage = std::string(bus::kStageStepWriter);
    spec.inputs = {{bus::Topic::Features, false}};
    spec.output = bus::Topic::Part21;
    spec.unregister_output_when_over = false;  // the result stays for `submit --wait` and late readers
    spec.open = [dir = std::filesystem::path(output_dir)](const service::JobKey&, service::JobContext& context)
        -> std::unique_ptr<service::JobStream> { return std::make_unique<WriterStream>(context, dir); };
    return spec;
  });
}
