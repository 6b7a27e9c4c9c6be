// model_footprint PROGRAM TOOLS STOCK [--streamed]: how much memory the CC1 conversion of a
// program takes, by stage. Whole: runs interpreter -> cc1_builder, measures the finished model
// (bytes its containers use) and the peak resident set, then writes the Part 21 text to a sink
// that only counts it. Streamed (as `ncbridge convert --level cc1`): the builder hands each
// element to the Part 21 writer at once; only the peak resident set is measured. Comparing two
// program lengths shows what grows with the program and what stays flat (figures in
// docs/performance.md, "CC1 conversion").
#include <cstdio>
#include <fstream>
#include <string>
#include <variant>

#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/step_writer/stepnc_stream_writer.hpp"

namespace {

using namespace ncbridge;

// Peak and current resident set of this process, kB (from /proc/self/status).
struct Resident {
  long peak_kb = 0, now_kb = 0;
};
Resident resident() {
  Resident r;
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmHWM:", 0) == 0) r.peak_kb = std::stol(line.substr(6));
    if (line.rfind("VmRSS:", 0) == 0) r.now_kb = std::stol(line.substr(6));
  }
  return r;
}

// Bytes the model's containers use beyond the Project value itself (sizes: the capacity beyond
// them is the vectors' growth slack, mostly never touched).
struct Footprint {
  std::size_t bytes = 0;
  template <class T>
  void vec(const std::vector<T>& v) { bytes += v.size() * sizeof(T); }
  void str(const std::string& s) {
    if (s.capacity() > 15) bytes += s.capacity() + 1;
  }
  void curve(const stepnc::CompositeCurve& c) {
    vec(c.segments);
    for (const auto& s : c.segments) {
      if (const auto* l = std::get_if<stepnc::Polyline>(&s)) vec(l->points);
    }
  }
  void toolpath(const std::optional<stepnc::ToolpathList>& t) {
    if (!t) return;
    vec(t->its_list);
    for (const auto& c : t->its_list) curve(c.basiccurve);
  }
  void project(const stepnc::Project& p) {
    vec(p.main_workplan.its_elements);
    for (const auto& e : p.main_workplan.its_elements) {
      std::visit([&](const auto& x) { str(x.its_id); }, e);
      if (const auto* r = std::get_if<stepnc::RapidMovement>(&e)) toolpath(r->its_toolpath);
    }
    vec(p.features);
    for (const auto& f : p.features) str(stepnc::feature_id(f));
    vec(p.operations);
    for (const auto& o : p.operations) {
      str(stepnc::machining_operation(o).its_id);
      toolpath(stepnc::machining_operation(o).its_toolpath);
    }
  }
};

// Counts what the builder is given: every call, and the moves among them.
class CountingSink final : public canonical::Sink {
 public:
  explicit CountingSink(canonical::Sink& next) : next_(next) {}
  void source_file(std::uint32_t index, std::string_view path) override { next_.source_file(index, path); }
  void call(const canonical::Call& c) override {
    ++calls;
    if (std::holds_alternative<canonical::StraightFeed>(c.data) || std::holds_alternative<canonical::ArcFeed>(c.data) ||
        std::holds_alternative<canonical::StraightTraverse>(c.data)) {
      ++moves;
    }
    next_.call(c);
  }
  void end() override { next_.end(); }
  std::uint64_t calls = 0, moves = 0;

 private:
  canonical::Sink& next_;
};

// Hands each finished element to the Part 21 writer and counts them.
class ElementCounter final : public cc1_builder::WorkplanSink {
 public:
  explicit ElementCounter(step_writer::StepncStreamWriter& writer) : writer_(writer) {}
  void element(const stepnc::Project& project, const stepnc::Executable& element) override {
    writer_.element(project, element);
    ++elements;
  }
  std::size_t elements = 0;

 private:
  step_writer::StepncStreamWriter& writer_;
};

int streamed(const cc1_builder::Options& options, const interpreter::Options& interp, const char* program) {
  std::uint64_t bytes = 0;
  step_writer::StepncStreamWriter writer({}, [&](std::string_view chunk) { bytes += chunk.size(); });
  ElementCounter elements(writer);
  cc1_builder::Cc1Builder builder(options, &elements);
  CountingSink sink(builder);
  interpreter::interpret_file(program, interp, sink);
  writer.finish(builder.take_project());
  const Resident done = resident();
  std::printf("streamed: calls %llu, moves %llu, workplan elements %zu, file %.1f MB\n",
              static_cast<unsigned long long>(sink.calls), static_cast<unsigned long long>(sink.moves), elements.elements,
              static_cast<double>(bytes) / 1e6);
  std::printf("peak RSS %.1f MB (interpreter, builder, writer and the program's code; no model is held)\n",
              static_cast<double>(done.peak_kb) / 1e3);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 && !(argc == 5 && std::string(argv[4]) == "--streamed")) {
    std::fprintf(stderr, "usage: model_footprint PROGRAM TOOLS STOCK [--streamed]\n");
    return 2;
  }
  try {
    cc1_builder::Options options;
    options.tools = setup::read_tool_list(argv[2]);
    options.stock = setup::read_stock(argv[3]);
    interpreter::Options interp;
    interp.tools = options.tools;
    if (argc == 5) return streamed(options, interp, argv[1]);
    cc1_builder::Cc1Builder builder(options);
    CountingSink sink(builder);
    interpreter::interpret_file(argv[1], interp, sink);
    const stepnc::Project project = builder.take_project();
    const Resident built = resident();
    Footprint model;
    model.project(project);
    std::uint64_t bytes = 0;
    step_writer::write_stepnc(project, {}, [&](std::string_view chunk) { bytes += chunk.size(); });
    const Resident written = resident();
    std::size_t workingsteps = project.main_workplan.its_elements.size();
    std::printf("calls %llu, moves %llu, workplan elements %zu, file %.1f MB\n",
                static_cast<unsigned long long>(sink.calls), static_cast<unsigned long long>(sink.moves),
                workingsteps, static_cast<double>(bytes) / 1e6);
    std::printf("model: %.1f MB used by its containers (%.0f B per move, %.0f B per workplan element)\n",
                static_cast<double>(model.bytes) / 1e6, static_cast<double>(model.bytes) / static_cast<double>(sink.moves),
                static_cast<double>(model.bytes) / static_cast<double>(workingsteps));
    std::printf("peak RSS after building %.1f MB (held %.1f MB), after writing %.1f MB: writer adds %.1f MB\n",
                static_cast<double>(built.peak_kb) / 1e3, static_cast<double>(built.now_kb) / 1e3,
                static_cast<double>(written.peak_kb) / 1e3,
                static_cast<double>(written.peak_kb - built.peak_kb) / 1e3);
    std::printf("peak RSS after building minus the model: %.1f MB (allocator headers and vector slack of the model, "
                "interpreter and builder working state, the program's code)\n",
                static_cast<double>(built.peak_kb) / 1e3 - static_cast<double>(model.bytes) / 1e6);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "model_footprint: %s\n", e.what());
    return 1;
  }
  return 0;
}
