// ncbridge-step-writer: the step_writer stage as a DDS service. A job's model stream from the
// features topic (ncbridge/service/model_stream.hpp) is decoded chunk by chunk as it arrives,
// then written as a Part 21 file with the same library calls (and so the same bytes) as
// `ncbridge convert`: into --output-dir (atomically), and onto the part21 topic in pieces of
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

class WriterStream final : public service::JobStream {
 public:
  WriterStream(service::JobContext& context, const std::filesystem::path& output_dir)
      : context_(context), output_dir_(output_dir), model_(context.job_id()) {}

  void sample(bus::Envelope sample) override {
    model_.sample(sample);
    if (model_.header() && sample.seq == 0) check_output_name(model_.header()->output_name);
  }

  void finish() override {
    const service::ModelHeader& header = *model_.header();
    const stepnc::Project project = model_.take();
    step_writer::StepncWriteOptions options;
    options.file_name = header.output_name;
    if (header.level == wire::ModelLevel::Cc2) options.description = {"ISO 14649 CC2 program written by ncbridge"};  // as convert
    wire::Part21File piece;
    piece.job_id = context_.job_id();
    piece.level = header.level == wire::ModelLevel::Cc2 ? wire::Part21Level::Cc2 : wire::Part21Level::Cc1;
    piece.file_name = header.output_name;
    const std::string subkey = piece.level == wire::Part21Level::Cc2 ? "cc2" : "cc1";
    std::optional<step_writer::AtomicFile> file;
    if (!output_dir_.empty()) file.emplace(output_dir_ / piece.file_name);
    // The file goes out in pieces as it is written: the reader receives while the writer writes.
    const auto publish = [&](bool last) {
      piece.sha256 = service::sha256(piece.content);
      piece.more = !last;
      context_.publish(subkey, piece.seq, 0, last, wire::encode_part21(piece));
      if (file) file->write(piece.content);
      piece.content.clear();
      ++piece.seq;
    };
    step_writer::write_stepnc(project, options, [&](std::string_view bytes) {
      piece.content.append(bytes);
      if (piece.content.size() >= kPieceBytes) publish(false);
    });
    publish(true);
    if (file) file->commit();
  }

 private:
  service::JobContext& context_;
  const std::filesystem::path& output_dir_;
  service::ModelReceiver model_;
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
