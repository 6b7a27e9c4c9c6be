// `ncbridge submit PROGRAM... --tools T --stock S [--wait] [-o OUT.stp | --output-dir DIR]`:
// publishes jobs on the programs topic for the running services (`ncbridge up`, deploy/).
// Several programs (files, directories of programs, or a --list file of "PROGRAM [TOOLS STOCK]"
// lines) go out from one DDS participant, all published at once, then awaited together: a bulk
// load pays discovery once. With --wait it shows the stages' progress (one job) or each job as it
// ends (several), and writes each job's Part 21 file (-o for one job, "-" for standard output;
// --output-dir for several, created when missing). Every output path is checked before a job is
// published; each job's file appears whole when the job is done (output_files.hpp), or not at
// all. The bus is the one CYCLONEDDS_URI and NCBRIDGE_DDS_DOMAIN name (or --domain).
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "client_bus.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "input_files.hpp"
#include "output_files.hpp"
#include "tool_source.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/routed_writer.hpp"
#include "ncbridge/bus/topics.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/service/job_watch.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/wire/job.hpp"

namespace ncbridge::cli {
namespace {

namespace fs = std::filesystem;

struct SubmitArguments {
  std::vector<std::string> programs;
  std::string list;
  ToolSource tools;
  std::string stock;
  std::string dialect = "rs274ngc";
  std::string level = "cc1";
  std::string output;
  std::string output_dir;
  std::string job_id;
  std::string subroutine_path;
  std::optional<std::uint32_t> domain;
  bool wait = false;
  bool detach = false;
  double timeout_s = 600;
};

// One program to submit, with the tool list and stock it is converted with.
struct Submission {
  std::string program;
  ToolSource tools;
  std::string stock;
};

wire::Dialect dialect_of(const std::string& name) {
  if (name == "fanuc") return wire::Dialect::Fanuc;
  if (name == "mach3") return wire::Dialect::Mach3;
  if (name == "siemens840d") return wire::Dialect::Siemens840D;
  if (name == "heidenhain") return wire::Dialect::Heidenhain;
  if (name == "auto") return wire::Dialect::Auto;
  return wire::Dialect::Rs274Ngc;
}

std::string read_text(const std::string& path, std::string_view what) {
  const Input input = open_input(path, what);
  if (input.text) return *input.text;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "cannot open (" + std::string(what) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool is_program_file(const fs::path& p) {
  static const std::set<std::string> kExtensions{".ngc", ".nc", ".tap", ".cnc", ".gcode", ".g", ".h", ".mpf", ".eia"};
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return kExtensions.contains(ext) && !p.filename().string().starts_with(".");
}

// The programs named on the command line (a directory: its program files, sorted) and in the
// list file ("PROGRAM [TOOLS STOCK]" per line, relative to the list's folder; # comments).
std::vector<Submission> submissions(const SubmitArguments& args) {
  std::vector<Submission> out;
  for (const std::string& p : args.programs) {
    if (p == "-" || !fs::is_directory(p)) {
      out.push_back({p, args.tools, args.stock});
      continue;
    }
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(p)) {
      if (entry.is_regular_file() && is_program_file(entry.path())) files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    if (files.empty()) throw InputError({p, 0, 0}, "no program files in this folder");
    for (std::string& f : files) out.push_back({std::move(f), args.tools, args.stock});
  }
  if (!args.list.empty()) {
    const fs::path base = fs::path(args.list).parent_path();
    const auto resolve = [&base](const std::string& p) { return fs::path(p).is_absolute() ? p : (base / p).string(); };
    std::istringstream lines(read_text(args.list, "--list"));
    std::uint32_t number = 0;
    for (std::string line; std::getline(lines, line);) {
      ++number;
      std::istringstream words(line);
      std::vector<std::string> w;
      for (std::string word; words >> word;) w.push_back(word);
      if (w.empty() || w[0].starts_with("#")) continue;
      if (w.size() != 1 && w.size() != 3)
        throw InputError({args.list, number, 1}, "expected PROGRAM or PROGRAM TOOLS STOCK");
      out.push_back({resolve(w[0]), w.size() == 3 ? ToolSource{resolve(w[1])} : args.tools, w.size() == 3 ? resolve(w[2]) : args.stock});
    }
  }
  std::size_t from_stdin = 0;
  for (const Submission& s : out) {
    if (!s.tools.given() || s.stock.empty())
      throw UsageError(s.program + ": no tool list or stock for this program (--tools or --tool-table, --stock, or the list's columns)");
    if (s.program == "-") ++from_stdin;
    else require_input_file(s.program, "program");
    s.tools.check();
    require_input_file(s.stock, "--stock");
  }
  if (from_stdin > 1) throw UsageError("standard input (-) can be one program only");
  return out;
}

std::string new_job_id(const std::string& program, std::mt19937& random) {
  char suffix[9];
  std::snprintf(suffix, sizeof suffix, "%08x", static_cast<unsigned>(random()));
  return fs::path(program).stem().string() + "-" + suffix;
}

const char* state_name(wire::JobState s) {
  switch (s) {
    case wire::JobState::Queued: return "queued";
    case wire::JobState::Running: return "running";
    case wire::JobState::Progress: return "progress";
    case wire::JobState::Done: return "done";
    case wire::JobState::Error: return "error";
    case wire::JobState::Delivered: return "delivered";
    case wire::JobState::Cancelled: return "cancelled";
  }
  return "?";
}

void print_job_error(const wire::JobStatus& e) {
  if (e.state == wire::JobState::Cancelled) print_error("job " + e.job_id + " was cancelled");
  else print_error(e.where, e.message + " (" + e.stage + ")");
}

// --detach: until the first stage has accepted every job: the worker that owns it has all of its
// input and says so on the status topic (running, or an error at once). Then the job no longer
// needs this process (docs/deployment.md, "What survives what").
// Only statuses are read: the files stay on the bus for `ncbridge fetch`.
int wait_for_acceptance(bus::Reader& statuses, const std::vector<std::string>& ids, std::chrono::milliseconds timeout) {
  std::set<std::string> waiting(ids.begin(), ids.end());
  std::size_t rejected = 0;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!waiting.empty() && std::chrono::steady_clock::now() < deadline) {
    for (const bus::Received& r : statuses.take(std::chrono::milliseconds(100), 4096)) {
      if (!r.has_data || !waiting.contains(r.envelope.key) || r.envelope.subkey != bus::kStageInterpreter) continue;
      const wire::JobStatus s = wire::decode_status(r.envelope.payload);
      if (s.state == wire::JobState::Error) {
        print_job_error(s);
        ++rejected;
      }
      waiting.erase(s.job_id);
    }
  }
  for (const std::string& id : waiting)
    print_error("job " + id + " not accepted by an interpreter within " + std::to_string(timeout.count() / 1000) + " s (--timeout)");
  if (!waiting.empty()) return exit_status::service_unavailable;
  return rejected > 0 ? exit_status::input_error : exit_status::ok;
}

std::string stem_of(const std::string& program) { return program == "-" ? "stdin" : fs::path(program).stem().string(); }

int run_submit(const SubmitArguments& args) {
  if (!args.list.empty()) require_input_file(args.list, "--list");
  const std::vector<Submission> list = submissions(args);
  if (list.empty()) throw UsageError("no program to submit");
  const bool single = list.size() == 1;
  if (!single && !args.job_id.empty()) throw UsageError("--job-id: only with one program");
  if (!single && !args.output.empty()) throw UsageError("-o: only with one program (several: --output-dir)");
  if (!args.output.empty() && !args.output_dir.empty()) throw UsageError("-o and --output-dir: give one");
  if (args.wait && args.detach) throw UsageError("--wait and --detach: give one");
  if (!args.wait && (!args.output.empty() || !args.output_dir.empty()))
    throw UsageError("-o and --output-dir need --wait (the files are written when the jobs end; later: ncbridge fetch JOB)");
  if (args.wait && single && args.output.empty() && args.output_dir.empty())
    throw UsageError("--wait needs -o or --output-dir");
  if (args.wait && !single && args.output_dir.empty()) throw UsageError("--wait with several programs needs --output-dir");
  const fs::path output_dir = args.output_dir.empty() ? fs::path() : prepare_output_directory(args.output_dir, "--output-dir");

  std::vector<std::string> subroutine_dirs;
  std::stringstream dirs(args.subroutine_path);
  for (std::string d; std::getline(dirs, d, ':');) {
    if (!d.empty()) subroutine_dirs.push_back(fs::absolute(d).string());
  }
  std::random_device seed;
  std::mt19937 random(seed());
  std::vector<wire::Job> jobs;
  // Each job's file, checked now; it appears when its job is done.
  struct JobOutput {
    OutputSet set;
    OutputFile* file = nullptr;
  };
  std::map<std::string, JobOutput> output_of;
  std::set<std::string> output_names;
  bool to_stdout = false;
  for (const Submission& s : list) {
    wire::Job job;
    job.job_id = single && !args.job_id.empty() ? args.job_id : new_job_id(stem_of(s.program), random);
    job.file_name = s.program == "-" ? "<stdin>" : s.program;
    job.program_text = read_text(s.program, "program");
    job.dialect = dialect_of(args.dialect);
    job.tools = s.tools.read().tools();
    job.stock = setup::read_stock(s.stock);
    job.level = args.level == "cc2" ? wire::ConformanceClass::Cc2 : wire::ConformanceClass::Cc1;
    job.output_name = stem_of(s.program) + ".stp";
    if (args.wait) {
      JobOutput& out = output_of[job.job_id];
      if (!args.output.empty()) {
        out.file = &out.set.add(args.output, "-o");
        if (!out.file->file_name().empty()) job.output_name = out.file->file_name();
        to_stdout = out.file->is_stream();
      } else {
        out.file = &out.set.add((output_dir / job.output_name).string(), "--output-dir");
      }
      for (const std::string* input : {&s.program, &s.tools.file(), &s.stock}) out.set.protect(*input);
    }
    if (!output_names.insert(job.output_name).second)
      throw UsageError(s.program + ": two programs would both be written as " + job.output_name);
    job.subroutine_path = subroutine_dirs;
    jobs.push_back(std::move(job));
  }

  const ClientBus bus = client_bus(args.domain);
  bus::Participant participant(bus.config);
  std::vector<std::string> ids;
  for (const wire::Job& j : jobs) ids.push_back(j.job_id);
  // Before publishing: nothing is missed.
  std::optional<service::JobWatch> watch;
  std::optional<bus::Reader> statuses;
  if (args.wait) watch.emplace(participant, ids);
  if (args.detach) statuses.emplace(participant, bus::Topic::Status);
  bus::RoutedWriter programs(participant, bus::Topic::Programs);  // each job to its interpreter only
  const auto timeout = std::chrono::milliseconds(static_cast<long long>(args.timeout_s * 1000));
  if (!programs.wait_for_readers(1, std::min(timeout, std::chrono::milliseconds(10'000)))) {
    throw ServiceUnavailable(no_service_message(bus, "interpreter"));
  }
  // The job ids go to standard output, unless the result does.
  std::FILE* ids_to = to_stdout ? stderr : stdout;
  for (const wire::Job& job : jobs) {
    programs.write(job.job_id, "", 0, 0, true, wire::encode_job(job));
    std::fprintf(ids_to, "%s\n", job.job_id.c_str());
  }
  std::fflush(ids_to);
  jobs.clear();  // the writer holds them now
  if (args.detach) return wait_for_acceptance(*statuses, ids, timeout);
  if (!args.wait) {
    // A job's only copy is this process's writer until an interpreter has it.
    programs.wait_for_acks(timeout);
    return 0;
  }
  const bool tty = isatty(STDERR_FILENO) != 0;
  int failed = 0, not_written = 0;
  // Each file goes to its temporary as its pieces come, and appears when whole.
  const auto on_piece = [&](const std::string& job_id, const wire::Part21File& piece) {
    output_of.at(job_id).file->write(piece.content);
  };
  const auto on_over = [&](const std::string& job_id, service::JobOutcome outcome) {
    if (tty && single) std::fprintf(stderr, "\r\033[K");
    const auto out = output_of.find(job_id);
    if (outcome.error) {
      print_job_error(*outcome.error);
      ++failed;
      output_of.erase(out);  // removes the part written
    } else {
      try {
        out->second.set.commit();
        if (!single) std::fprintf(stderr, "%s: done, %s\n", job_id.c_str(), out->second.file->display_name().c_str());
      } catch (const OutputError& e) {
        print_error({e.path().string(), 0, 0}, e.message());
        ++not_written;
      }
      output_of.erase(out);
    }
    programs.unregister(job_id, "");
  };
  const auto on_status = [&](const wire::JobStatus& s) {
    if (!single || (s.state == wire::JobState::Progress && !tty)) return;
    std::fprintf(stderr, "%s%s: %s", tty ? "\r\033[K" : "", s.stage.c_str(), state_name(s.state));
    if (s.state == wire::JobState::Progress) std::fprintf(stderr, " %3.0f%%", s.progress * 100);
    std::fprintf(stderr, "%s", tty ? "" : "\n");
  };
  const std::set<std::string> late = watch->wait_all(timeout, on_piece, on_over, on_status);
  for (const std::string& id : late) print_error("job " + id + " not done after " + std::to_string(static_cast<long long>(args.timeout_s)) + " s (--timeout)");
  if (!single) std::fprintf(stderr, "%zu jobs: %zu done, %d failed, %zu not done\n", ids.size(), ids.size() - failed - late.size(), failed, late.size());
  if (!late.empty()) return exit_status::service_unavailable;
  if (not_written > 0) return exit_status::output_error;
  return failed > 0 ? exit_status::input_error : exit_status::ok;
}

}  // namespace

void add_submit_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<SubmitArguments>();
  CLI::App* cmd = app.add_subcommand("submit", "Submit part programs to the running DDS services");
  cmd->add_option("programs", args->programs, "Part programs, or folders of them; - reads one from standard input");
  cmd->add_option("--list", args->list, "File of \"PROGRAM [TOOLS STOCK]\" lines to submit too");
  add_tool_source_options(*cmd, args->tools, "");
  cmd->add_option("--stock", args->stock, "Stock block (JSON or YAML)");
  cmd->add_option("--dialect", args->dialect, "Program dialect")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain", "auto"}));
  cmd->add_option("--level", args->level, "Conformance class asked for")->check(CLI::IsMember({"cc1", "cc2"}));
  cmd->add_option("-o,--output", args->output, "Part 21 file to write (one program, with --wait; - for standard output)");
  cmd->add_option("--output-dir", args->output_dir, "Directory for the Part 21 files (with --wait), named PROGRAM-STEM.stp; created when missing");
  cmd->add_option("--job-id", args->job_id, "Job id, one program only (default: program name + random suffix)");
  cmd->add_option("--subroutine-path", args->subroutine_path, "Directories searched for o<name> call files, ':'-separated");
  cmd->add_option("--domain", args->domain, "DDS domain id (default: NCBRIDGE_DDS_DOMAIN, else the running ncbridge up's)")->check(CLI::Range(0, 230));
  cmd->add_flag("--wait", args->wait, "Show progress and write the results");
  cmd->add_flag("--detach", args->detach,
                "Return once the interpreters have accepted every job; the jobs go on without this client "
                "(their files: ncbridge fetch JOB, or up --output-dir)");
  cmd->add_option("--timeout", args->timeout_s, "Seconds to wait (default 600)");
  cmd->callback([args, &exit_code]() { exit_code = run_submit(*args); });
}

}  // namespace ncbridge::cli
