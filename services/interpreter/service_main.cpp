// ncbridge-interpreter: the interpreter stage as a DDS service. Jobs come from the programs
// topic (a whole program) and from the blocks topic (a controller's run, live capture: the run's
// blocks in order, interpreted when its RUN_END arrives). Each job's canonical stream goes to
// the canonical topic: the job context first, then batches (ncbridge/service/canonical_stream.hpp).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <optional>
#include <string>

#include "ncbridge/bus/canonical_batcher.hpp"
#include "ncbridge/bus/topics.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/service/canonical_stream.hpp"
#include "ncbridge/service/service_options.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/wire/block.hpp"
#include "ncbridge/wire/job.hpp"

namespace {

using namespace ncbridge;

// What live-capture runs are converted with: the machine's tools and stock (a controller's
// blocks carry neither).
struct LiveSetup {
  std::string tools;
  std::string tool_table;  // a LinuxCNC tool table instead of `tools`
  std::string tool_table_units = "mm";
  std::string stock;
  std::string dialect = "rs274ngc";
  std::string level = "cc1";
};

wire::Dialect dialect_of(const std::string& name) {
  if (name == "fanuc") return wire::Dialect::Fanuc;
  if (name == "mach3") return wire::Dialect::Mach3;
  if (name == "siemens840d") return wire::Dialect::Siemens840D;
  if (name == "heidenhain") return wire::Dialect::Heidenhain;
  if (name == "auto") return wire::Dialect::Auto;
  return wire::Dialect::Rs274Ngc;
}

wire::Job job_from_program(const service::JobInput& input) {
  // A resubmission of the same job id replaces the program: the latest sample counts.
  wire::Job job = wire::decode_job(input.payloads.back());
  if (job.job_id != input.job_id)
    throw InputError({"<job>", 0, 0}, "the payload is not a job for \"" + input.job_id + "\" (it names \"" +
                                          job.job_id + "\")");
  return job;
}

// The tools a captured run is read with: the controller's own tool table when its RUN_START
// carries one (diameters and lengths as the machine uses them), each tool's type and name from
// the --live-tools list where it has the same number (a LinuxCNC table has no tool types).
std::vector<setup::Tool> run_tools(const wire::ExecutedBlock& start, const std::vector<setup::Tool>& live,
                                   const std::string& job_id) {
  if (start.tool_table.empty()) return live;
  const setup::ToolList table = setup::parse_linuxcnc_tool_table(
      start.tool_table, start.tool_table_inch ? setup::LengthUnits::Inches : setup::LengthUnits::Millimeters,
      "<tool table of run " + job_id + ">");
  std::vector<setup::Tool> tools;
  for (setup::Tool t : table.tools()) {
    const auto named = std::find_if(live.begin(), live.end(), [&](const setup::Tool& l) { return l.number == t.number; });
    if (named != live.end()) {
      t.name = named->name;
      t.type = named->type;
      t.corner_radius = named->corner_radius;
      t.flute_length = named->flute_length;
      t.flutes = named->flutes;
      t.point_angle = named->point_angle;
      t.thread_pitch = named->thread_pitch;
    }
    tools.push_back(std::move(t));
  }
  return tools;
}

// A run of executed blocks becomes a program: the blocks in seq order, one per line, so source
// lines are block numbers of the run (1 = the first executed block). A run the controller
// stopped before the program's end is an error naming why: a half run never becomes a file.
wire::Job job_from_run(const service::JobInput& input, const wire::Job& live) {
  wire::Job job = live;
  job.job_id = input.job_id;
  std::string name = input.job_id;
  for (char& c : name) {
    if (c == '/') c = '-';
  }
  job.output_name = name + ".stp";
  job.file_name = input.job_id;
  std::uint64_t blocks = 0;
  for (const std::string& payload : input.payloads) {
    const wire::ExecutedBlock block = wire::decode_block(payload);
    if (block.kind == wire::BlockKind::RunStart) {
      if (!block.text.empty()) job.file_name = block.text;
      job.tools = run_tools(block, live.tools, input.job_id);
    }
    if (block.kind == wire::BlockKind::RunEnd && block.aborted) {
      throw InputError({job.file_name, 0, 0}, "run aborted by the controller after " + std::to_string(blocks) +
                                                  " blocks (" + block.reason + "): no file is made of a half run");
    }
    if (block.kind != wire::BlockKind::Block) continue;
    ++blocks;
    job.program_text += block.text;
    job.program_text += '\n';
  }
  return job;
}

// Forwards the stream, reporting progress as the share of the program's lines interpreted.
class ProgressSink final : public canonical::Sink {
 public:
  ProgressSink(canonical::Sink& next, service::JobContext& context, std::string_view text)
      : next_(next), context_(context), lines_(1.0 + static_cast<double>(std::count(text.begin(), text.end(), '\n'))) {}
  void source_file(std::uint32_t index, std::string_view path) override { next_.source_file(index, path); }
  void call(const canonical::Call& c) override {
    next_.call(c);
    if ((++calls_ & 0x3FF) == 0) context_.progress(static_cast<double>(c.source.line) / lines_);
  }
  void end() override { next_.end(); }

 private:
  canonical::Sink& next_;
  service::JobContext& context_;
  double lines_;
  std::uint64_t calls_ = 0;
};

void interpret(const wire::Job& job, service::JobContext& context) {
  interpreter::Options options;
  options.dialect = static_cast<interpreter::Dialect>(job.dialect);
  options.tools = setup::ToolList(job.tools);
  for (const std::string& dir : job.subroutine_path) options.subroutine_path.emplace_back(dir);

  wire::Job header = job;
  header.program_text.clear();
  context.publish("", 0, service::kJobContext, false, wire::encode_job(header));

  bus::CanonicalBatcher batcher(job.job_id, 1024, [&context](const bus::Envelope& batch) {
    context.publish("", batch.seq + 1, service::kCanonicalBatch, batch.last, batch.payload);  // after the context
  });
  ProgressSink sink(batcher, context, job.program_text);
  interpreter::interpret_text(job.program_text, job.file_name, options, sink);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ncbridge-interpreter: part programs and controller runs -> canonical calls (DDS service)",
               "ncbridge-interpreter"};
  service::ServiceOptions options;
  service::add_service_options(app, options);
  LiveSetup live;
  app.add_option("--live-tools", live.tools, "Tool list for live-capture runs (JSON/YAML)")->check(CLI::ExistingFile);
  app.add_option("--live-tool-table", live.tool_table, "LinuxCNC tool table (.tbl) for live-capture runs, instead of --live-tools")
      ->check(CLI::ExistingFile)
      ->excludes("--live-tools");
  app.add_option("--live-tool-table-units", live.tool_table_units, "Units of the tool table values (default mm)")
      ->check(CLI::IsMember({"mm", "inch"}));
  app.add_option("--live-stock", live.stock, "Stock for live-capture runs (JSON/YAML)")->check(CLI::ExistingFile);
  app.add_option("--live-dialect", live.dialect, "Dialect of live-capture runs")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain", "auto"}));
  app.add_option("--live-level", live.level, "Conformance class asked for live-capture runs")
      ->check(CLI::IsMember({"cc1", "cc2"}));

  return service::run_service(argc, argv, app, options, [&] {
    wire::Job live_job;
    live_job.dialect = dialect_of(live.dialect);
    if (!live.tools.empty()) live_job.tools = setup::read_tool_list(live.tools).tools();
    if (!live.tool_table.empty()) {
      const auto units = live.tool_table_units == "inch" ? setup::LengthUnits::Inches : setup::LengthUnits::Millimeters;
      live_job.tools = setup::read_linuxcnc_tool_table(live.tool_table, units).tools();
    }
    if (!live.stock.empty()) live_job.stock = setup::read_stock(live.stock);
    live_job.level = live.level == "cc2" ? wire::ConformanceClass::Cc2 : wire::ConformanceClass::Cc1;
    service::StageSpec spec;
    spec.stage = std::string(bus::kStageInterpreter);
    spec.inputs = {{bus::Topic::Programs, false}, {bus::Topic::Blocks, true}};
    spec.output = bus::Topic::Canonical;
    spec.run = [live_job](const service::JobInput& input, service::JobContext& context) {
      interpret(input.topic == bus::Topic::Blocks ? job_from_run(input, live_job) : job_from_program(input), context);
    };
    return spec;
  });
}
