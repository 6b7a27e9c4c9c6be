// `ncbridge controller-sim PROGRAM --controller ID [--rate BLOCKS/S]`: publishes a program on
// the blocks topic as a controller executing it would: RUN_START (text: the program's name),
// one BLOCK per block as it is executed (seq 1, 2, ...; `line` = its line in the program), then
// RUN_END, all on the instance (controller id, run id). The interpreter service turns the run
// into job "ID/RUN" when RUN_END arrives; the command waits for that job's outcome (exit 1 when
// the run failed, 4 when it did not end within --timeout) unless --no-wait.
//
// The program's control flow runs here, as on a controller (RS274/NGC, the default): loops and
// branches are taken and subroutines called by our interpreter, and what is published is the
// sequence of blocks executed, without the o-word lines that steered it, so a block in a loop
// is published once per pass and a subroutine's blocks once per call. A call's arguments are
// published as the parameter setting "#1=[...] #2=[...]" that the call performs (the order is
// capture::execution_order, services/capture/, which live capture also uses). Not expanded: subroutines in
// other files (o<name> call of a file on the subroutine path: their blocks are not published)
// and the restoring of the caller's #1-#30 after a call returns. Other dialects are published
// line by line as written (their control flow is not run here).
#include <CLI/CLI.hpp>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "client_bus.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "input_files.hpp"
#include "output_files.hpp"
#include "tool_source.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/writer.hpp"
#include "ncbridge/capture/execution_order.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/service/job_watch.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/wire/block.hpp"

namespace ncbridge::cli {
namespace {

struct ControllerSimArguments {
  std::string program;
  std::string controller;
  std::string run_id;
  ToolSource tools;
  std::string dialect = "rs274ngc";
  double rate = 0;  // blocks per second, 0 = as fast as the bus takes them
  std::optional<std::uint32_t> domain;
  std::string output;
  bool no_wait = false;
  double timeout_s = 600;
};

int run_controller_sim(const ControllerSimArguments& args) {
  args.tools.check();
  OutputSet outputs;
  OutputFile* output = args.output.empty() ? nullptr : &outputs.add(args.output, "-o");
  outputs.protect(args.program);
  outputs.protect(args.tools.file());
  const Input program = open_input(args.program, "program");
  std::string text;
  if (program.text) {
    text = *program.text;
  } else {
    std::ifstream in(program.path, std::ios::binary);
    if (!in) throw InputError({program.name, 0, 0}, "cannot open program file");
    std::ostringstream read;
    read << in.rdbuf();
    text = read.str();
  }
  const setup::ToolList tools = args.tools.read();
  interpreter::Dialect dialect = interpreter::Dialect::Rs274Ngc;
  interpreter::parse_dialect_name(args.dialect, dialect);
  const std::vector<capture::ExecutedLine> blocks = capture::execution_order(program.name, text, tools, dialect);

  std::string run_id = args.run_id;
  if (run_id.empty()) {
    run_id = "run-" + std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(
                                         std::chrono::system_clock::now().time_since_epoch()).count());
  }
  const std::string job_id = args.controller + "/" + run_id;

  const ClientBus bus = client_bus(args.domain);
  bus::Participant participant(bus.config);
  std::optional<service::JobWatch> watch;
  if (!args.no_wait) watch.emplace(participant, job_id);
  bus::Writer writer(participant, bus::Topic::Blocks);
  if (!writer.wait_for_readers(1, std::chrono::seconds(10))) {
    throw ServiceUnavailable(no_service_message(bus, "interpreter"));
  }
  const auto period = args.rate > 0 ? std::chrono::duration<double>(1.0 / args.rate) : std::chrono::duration<double>(0);
  auto next = std::chrono::steady_clock::now();
  std::uint64_t seq = 0;
  const auto publish = [&](wire::BlockKind kind, std::string block_text, std::uint32_t line) {
    wire::ExecutedBlock b{args.controller, run_id, seq, kind, std::move(block_text), line};
    writer.write(args.controller, run_id, seq, static_cast<std::uint32_t>(kind), kind == wire::BlockKind::RunEnd,
                 wire::encode_block(b));
    ++seq;
  };
  publish(wire::BlockKind::RunStart, program.name, 0);
  for (const capture::ExecutedLine& block : blocks) {
    if (period.count() > 0) {
      next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
      std::this_thread::sleep_until(next);
    }
    publish(wire::BlockKind::Block, block.text, block.line);
  }
  publish(wire::BlockKind::RunEnd, "", 0);
  const auto run_end = std::chrono::steady_clock::now();
  std::printf("%s\n", job_id.c_str());
  std::fflush(stdout);
  const auto timeout = std::chrono::milliseconds(static_cast<long long>(args.timeout_s * 1000));
  if (!watch) {
    writer.wait_for_acks(timeout);
    return 0;
  }
  const service::JobOutcome outcome = watch->wait(timeout);
  if (outcome.error) {
    const wire::JobStatus& e = *outcome.error;
    if (e.state == wire::JobState::Cancelled) print_error("run " + job_id + " was cancelled");
    else print_error(e.where, e.message + " (" + e.stage + ")");
    return exit_status::input_error;
  }
  if (!outcome.file) {
    throw ServiceUnavailable("run " + job_id + " not converted after " + std::to_string(static_cast<long long>(args.timeout_s)) +
                             " s (--timeout)");
  }
  if (output != nullptr) {
    output->write(outcome.file->content);
    outputs.commit();
  }
  std::fprintf(stderr, "%zu blocks executed; run end to %s file: %.1f ms\n", blocks.size(),
               outcome.file->level == wire::Part21Level::Cc2 ? "CC2" : "CC1",
               std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - run_end).count());
  return 0;
}

}  // namespace

void add_controller_sim_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ControllerSimArguments>();
  CLI::App* cmd = app.add_subcommand("controller-sim", "Publish a program block by block as a controller running it");
  cmd->add_option("program", args->program, "Part program; - reads standard input")->required();
  cmd->add_option("--controller", args->controller, "Controller id")->required();
  cmd->add_option("--run-id", args->run_id, "Run id (default: run-<unix ms>)");
  add_tool_source_options(*cmd, args->tools, ": the controller's tools, for running the program");
  cmd->add_option("--dialect", args->dialect, "Program dialect; control flow is run for rs274ngc only")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain"}));
  cmd->add_option("--rate", args->rate, "Blocks per second (default: as fast as possible)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--domain", args->domain, "DDS domain id (default: NCBRIDGE_DDS_DOMAIN, else the running ncbridge up's)")->check(CLI::Range(0, 230));
  CLI::Option* output =
      cmd->add_option("-o,--output", args->output, "Write the run's Part 21 file here (- for standard output)");
  cmd->add_flag("--no-wait", args->no_wait, "Publish the run and exit, without waiting for its conversion")->excludes(output);
  cmd->add_option("--timeout", args->timeout_s, "Seconds to wait for the run's conversion (default 600)");
  cmd->callback([args, &exit_code]() { exit_code = run_controller_sim(*args); });
}

}  // namespace ncbridge::cli
