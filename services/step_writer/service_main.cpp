// ncbridge-step-writer: the step_writer stage as a DDS service. A job's model from the features
// topic is written as a Part 21 file, with the same library calls (and so the same bytes) as
// `ncbridge convert`: into --output-dir (atomically), and onto the part21 topic with its digest.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>

#include "ncbridge/bus/topics.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/service/service_options.hpp"
#include "ncbridge/service/sha256.hpp"
#include "ncbridge/step_writer/atomic_file.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/stepnc_codec/project_codec.hpp"
#include "ncbridge/wire/part21.hpp"
#include "ncbridge/wire/workingsteps.hpp"

namespace {

using namespace ncbridge;

// The output name comes from the job's submitter: a bare file name, nothing that leaves the
// output directory.
void check_output_name(const std::string& name) {
  const std::filesystem::path p(name);
  if (name.empty() || p.filename() != p || name == "." || name == "..")
    throw InputError({"<stepnc model>", 0, 0}, "output name \"" + name + "\" is not a plain file name");
}

void write(const service::JobInput& input, service::JobContext& context, const std::filesystem::path& output_dir) {
  const wire::StepncModel model = wire::decode_stepnc_model(input.payloads.back());
  if (model.job_id != input.job_id)
    throw InputError({"<stepnc model>", 0, 0}, "a model of job \"" + model.job_id + "\" in job \"" + input.job_id + "\"");
  check_output_name(model.output_name);
  const stepnc::Project project = stepnc_codec::decode_project(model.model);
  step_writer::StepncWriteOptions options;
  options.file_name = model.output_name;
  if (model.level == wire::ModelLevel::Cc2) options.description = {"ISO 14649 CC2 program written by ncbridge"};  // as convert
  wire::Part21File file;
  file.job_id = input.job_id;
  file.level = model.level == wire::ModelLevel::Cc2 ? wire::Part21Level::Cc2 : wire::Part21Level::Cc1;
  file.file_name = model.output_name;
  file.content = step_writer::write_stepnc(project, options);
  file.sha256 = service::sha256(file.content);
  if (!output_dir.empty()) step_writer::write_file_atomically(output_dir / file.file_name, file.content);
  context.output().write(input.job_id, file.level == wire::Part21Level::Cc2 ? "cc2" : "cc1", 0, 0, true,
                         wire::encode_part21(file));
}

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
    spec.run = [dir = std::filesystem::path(output_dir)](const service::JobInput& input, service::JobContext& context) {
      write(input, context, dir);
    };
    return spec;
  });
}
