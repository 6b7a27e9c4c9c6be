// `ncbridge submit PROGRAM --tools T --stock S [--wait] -o OUT.stp`: publishes a job on the
// programs topic for the running services (`ncbridge up`, deploy/). With --wait it shows the
// stages' progress from the status topic and writes the job's Part 21 file to OUT.stp.
// The bus is the one CYCLONEDDS_URI and NCBRIDGE_DDS_DOMAIN name (or --domain).
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/writer.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/service/job_watch.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/atomic_file.hpp"
#include "ncbridge/wire/job.hpp"

namespace ncbridge::cli {
namespace {

struct SubmitArguments {
  std::string program;
  std::string tools;
  std::string stock;
  std::string dialect = "rs274ngc";
  std::string level = "cc1";
  std::string output;
  std::string job_id;
  std::string subroutine_path;
  std::optional<std::uint32_t> domain;
  bool wait = false;
  double timeout_s = 600;
};

wire::Dialect dialect_of(const std::string& name) {
  if (name == "fanuc") return wire::Dialect::Fanuc;
  if (name == "mach3") return wire::Dialect::Mach3;
  if (name == "siemens840d") return wire::Dialect::Siemens840D;
  if (name == "heidenhain") return wire::Dialect::Heidenhain;
  if (name == "auto") return wire::Dialect::Auto;
  return wire::Dialect::Rs274Ngc;
}

std::string read_program(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "cannot open program file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string new_job_id(const std::string& program) {
  std::random_device rd;
  char suffix[9];
  std::snprintf(suffix, sizeof suffix, "%08x", rd());
  return std::filesystem::path(program).stem().string() + "-" + suffix;
}

const char* state_name(wire::JobState s) {
  switch (s) {
    case wire::JobState::Queued: return "queued";
    case wire::JobState::Running: return "running";
    case wire::JobState::Progress: return "progress";
    case wire::JobState::Done: return "done";
    case wire::JobState::Error: return "error";
  }
  return "?";
}

int run_submit(const SubmitArguments& args) {
  wire::Job job;
  job.job_id = args.job_id.empty() ? new_job_id(args.program) : args.job_id;
  job.file_name = args.program;
  job.program_text = read_program(args.program);
  job.dialect = dialect_of(args.dialect);
  job.tools = setup::read_tool_list(args.tools).tools();
  job.stock = setup::read_stock(args.stock);
  job.level = args.level == "cc2" ? wire::ConformanceClass::Cc2 : wire::ConformanceClass::Cc1;
  job.output_name = args.output.empty() ? std::filesystem::path(args.program).stem().string() + ".stp"
                                        : std::filesystem::path(args.output).filename().string();
  std::stringstream dirs(args.subroutine_path);
  for (std::string d; std::getline(dirs, d, ':');) {
    if (!d.empty()) job.subroutine_path.push_back(std::filesystem::absolute(d).string());
  }

  bus::BusConfig config = bus::config_from_environment();
  if (args.domain) config.domain_id = *args.domain;
  bus::Participant participant(config);
  service::JobWatch watch(participant, job.job_id);  // before publishing: nothing is missed
  bus::Writer programs(participant, bus::Topic::Programs);
  const auto timeout = std::chrono::milliseconds(static_cast<long long>(args.timeout_s * 1000));
  if (!programs.wait_for_readers(1, std::min(timeout, std::chrono::milliseconds(10'000)))) {
    std::fprintf(stderr, "ncbridge submit: no interpreter service on DDS domain %u (is `ncbridge up` running?)\n",
                 participant.domain_id());
    return 3;
  }
  programs.write(job.job_id, "", 0, 0, true, wire::encode_job(job));
  std::printf("%s\n", job.job_id.c_str());
  std::fflush(stdout);
  if (!args.wait) {
    // The job's only copy is this process's writer until an interpreter has it.
    programs.wait_for_acks(timeout);
    return 0;
  }
  const bool tty = isatty(STDERR_FILENO) != 0;
  const service::JobOutcome outcome = watch.wait(timeout, [&](const wire::JobStatus& s) {
    if (s.state == wire::JobState::Progress && !tty) return;
    std::fprintf(stderr, "%s%s: %s", tty ? "\r\033[K" : "", s.stage.c_str(), state_name(s.state));
    if (s.state == wire::JobState::Progress) std::fprintf(stderr, " %3.0f%%", s.progress * 100);
    std::fprintf(stderr, "%s", tty ? "" : "\n");
  });
  if (tty) std::fprintf(stderr, "\r\033[K");
  if (outcome.error) {
    const wire::JobStatus& e = *outcome.error;
    std::fprintf(stderr, "%s: error: %s (%s)\n", e.where.to_string().c_str(), e.message.c_str(), e.stage.c_str());
    return 1;
  }
  if (!outcome.file) {
    std::fprintf(stderr, "ncbridge submit: job %s not done after %.0f s\n", job.job_id.c_str(), args.timeout_s);
    return 3;
  }
  step_writer::write_file_atomically(args.output, outcome.file->content);
  programs.unregister(job.job_id, "");
  return 0;
}

}  // namespace

void add_submit_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<SubmitArguments>();
  CLI::App* cmd = app.add_subcommand("submit", "Submit a part program to the running DDS services");
  cmd->add_option("program", args->program, "Part program")->required()->check(CLI::ExistingFile);
  cmd->add_option("--tools", args->tools, "Tool list (JSON or YAML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--stock", args->stock, "Stock block (JSON or YAML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--dialect", args->dialect, "Program dialect")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain", "auto"}));
  cmd->add_option("--level", args->level, "Conformance class asked for")->check(CLI::IsMember({"cc1", "cc2"}));
  cmd->add_option("-o,--output", args->output, "Part 21 file to write (with --wait); its name is FILE_NAME.name");
  cmd->add_option("--job-id", args->job_id, "Job id (default: program name + random suffix)");
  cmd->add_option("--subroutine-path", args->subroutine_path, "Directories searched for o<name> call files, ':'-separated");
  cmd->add_option("--domain", args->domain, "DDS domain id (default: NCBRIDGE_DDS_DOMAIN, else 0)")->check(CLI::Range(0, 230));
  cmd->add_flag("--wait", args->wait, "Show progress and write the result");
  cmd->add_option("--timeout", args->timeout_s, "Seconds to wait (default 600)");
  cmd->callback([args, &exit_code]() {
    if (args->wait && args->output.empty()) throw CLI::RequiredError("--output (with --wait)");
    exit_code = run_submit(*args);
  });
}

}  // namespace ncbridge::cli
