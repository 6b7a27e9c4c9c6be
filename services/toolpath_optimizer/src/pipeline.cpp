// optimize(): front-end -> optimizer -> writer, with the checker on both ends (pipeline.hpp).
#include "ncbridge/toolpath_optimizer/pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "ncbridge/common/error.hpp"
#include "ncbridge/toolpath_optimizer/block_count.hpp"
#include "ncbridge/toolpath_optimizer/canonical_bridge.hpp"
#include "ncbridge/toolpath_optimizer/printer_writer.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

using Clock = std::chrono::steady_clock;

// Hands each element to the next stage, recording the path on the way when asked.
class Tee final : public ElementSink {
 public:
  Tee(ElementSink& next, PathRecorder* recorder) : next_(next), recorder_(recorder) {}
  void element(Element&& e) override {
    if (recorder_ && std::holds_alternative<Motion>(e.item)) {
      Element copy{std::get<Motion>(e.item)};
      recorder_->element(std::move(copy));
    }
    next_.element(std::move(e));
  }
  void end() override { next_.end(); }

 private:
  ElementSink& next_;
  PathRecorder* recorder_;
};

// Calls progress every 64k motions.
class Progress final : public ElementSink {
 public:
  Progress(ElementSink& next, const std::function<void(std::uint64_t)>& progress) : next_(next), progress_(progress) {}
  void element(Element&& e) override {
    if (progress_ && (++count_ & 0xFFFF) == 0) {
      std::uint32_t line = 0;
      if (const auto* m = std::get_if<Motion>(&e.item)) line = m->source.line;
      else if (const auto* t = std::get_if<TextLine>(&e.item)) line = t->line;
      progress_(line);
    }
    next_.element(std::move(e));
  }
  void end() override { next_.end(); }

 private:
  ElementSink& next_;
  const std::function<void(std::uint64_t)>& progress_;
  std::uint64_t count_ = 0;
};

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

BlockCounts count_file_blocks(const std::filesystem::path& path, bool heidenhain) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.string().c_str(), "rb"), &std::fclose);
  if (!file) throw InputError({path.string(), 0, 0}, "cannot open the file");
  BlockCounter counter(heidenhain);
  std::string buffer(1 << 20, '\0');
  for (std::size_t got; (got = std::fread(buffer.data(), 1, buffer.size(), file.get())) > 0;) {
    counter.text(std::string_view(buffer.data(), got));
  }
  return counter.finish();
}

}  // namespace

OptimizeResult optimize(const OptimizeRequest& request, const OutputSinks& output) {
  const auto t0 = Clock::now();
  OptimizeResult result;
  if (!(request.optimizer.tolerance_mm > 0)) {
    throw InputError({request.input.string(), 0, 0}, "the tolerance must be greater than 0");
  }
  const bool cnc = request.input_kind == InputKind::Cnc;
  if (cnc && request.output == OutputFormat::PrinterGcode) {
    throw InputError({request.input.string(), 0, 0}, "a CNC program is not written as printer G-code: say --to");
  }
  if (request.loops && request.output == OutputFormat::PrinterGcode) {
    throw InputError({request.input.string(), 0, 0}, "printer G-code has no loop construct: --loops needs --to krl or a CNC dialect");
  }
  const bool krl = request.output == OutputFormat::Krl;
  OptimizerOptions optimizer_options = request.optimizer;
  KrlOptions krl_options = request.krl;
  if (krl) {
    // CIRC is a plane circle through an auxiliary point written with krl.decimals.
    optimizer_options.helical = false;
    optimizer_options.margin_mm = std::max(optimizer_options.margin_mm, 3 * std::pow(10.0, -krl_options.decimals));
    krl_options.extruder = !cnc;
    krl_options.approximation_mm = request.optimizer.tolerance_mm;
    if (krl_options.source.empty()) krl_options.source = request.input.filename().string();
  }

  PathRecorder input_path, output_path;
  PathRecorder* in_rec = request.check ? &input_path : nullptr;
  Clock::duration check_time{};
  // The written text, read back by the output's own front-end: printer lines as they come, the
  // KRL program when it is whole.
  std::unique_ptr<PrinterReader> back;
  std::string krl_text;
  if (request.check && !krl) back = std::make_unique<PrinterReader>(request.output_name, request.flavor, output_path);
  auto out_main = [&](std::string_view chunk) {
    output.main(chunk);
    if (!request.check) return;
    const auto t = Clock::now();
    if (back) back->text(chunk);
    else krl_text.append(chunk);
    check_time += Clock::now() - t;
  };
  std::unique_ptr<ElementSink> writer;
  PrinterWriter* printer_writer = nullptr;
  KrlWriter* krl_writer = nullptr;
  if (krl) {
    auto w = std::make_unique<KrlWriter>(krl_options, out_main, output.data);
    krl_writer = w.get();
    writer = std::move(w);
  } else {
    auto w = std::make_unique<PrinterWriter>(out_main);
    printer_writer = w.get();
    writer = std::move(w);
  }
  std::unique_ptr<LoopDetector> loops;
  ElementSink* after_optimizer = writer.get();
  if (request.loops) {
    loops = std::make_unique<LoopDetector>(request.loop, *writer);
    after_optimizer = loops.get();
  }
  Optimizer optimizer(optimizer_options, *after_optimizer);
  Tee tee(optimizer, in_rec);
  Progress progress(tee, request.progress);
  if (cnc) {
    const BlockCounts in = count_file_blocks(request.input, request.cnc.dialect == interpreter::Dialect::Heidenhain);
    result.bytes_in = in.bytes;
    result.lines_in = in.lines;
    result.commands_in = in.commands;
    result.motion_blocks_in = in.motion_blocks;
    result.arcs_in = in.arcs;
    CanonicalFrontEnd front_end(progress);
    interpreter::interpret_file(request.input, request.cnc, front_end);
  } else {
    const PrinterCounts in = read_printer_file(request.input, request.flavor, progress);
    result.bytes_in = in.bytes;
    result.lines_in = in.lines;
    result.commands_in = in.commands;
    result.motion_blocks_in = in.motion_blocks;
    result.arcs_in = in.arcs;
  }
  if (printer_writer) {
    result.bytes_out = printer_writer->bytes();
    result.lines_out = printer_writer->lines();
    result.commands_out = printer_writer->commands();
    result.motion_blocks_out = printer_writer->motion_blocks();
  } else {
    result.lines_out = krl_writer->lines();
    result.commands_out = krl_writer->commands();
    result.motion_blocks_out = krl_writer->motion_statements();
  }
  result.stats = optimizer.stats();
  if (loops) result.loops = loops->stats();
  if (request.check) {
    const auto t = Clock::now();
    if (back) back->finish();
    else read_krl_text(krl_text, request.output_name, output_path);
    DeviationOptions options;
    options.tolerance = request.optimizer.tolerance_mm;
    result.deviation = check_deviation(input_path.pieces, output_path.pieces, options);
    check_time += Clock::now() - t;
    result.check_seconds = seconds(check_time);
    if (!result.deviation->passed(options.tolerance)) {
      std::string what = "the output leaves the band: largest deviation " + std::to_string(result.deviation->largest()) +
                         " mm at output line " + std::to_string(result.deviation->worst_output_line);
      for (const auto& p : result.deviation->problems) what += "; " + p;
      throw std::runtime_error(what);
    }
  }
  result.optimize_seconds = seconds(Clock::now() - t0);
  return result;
}

std::string summary_line(const OptimizeRequest& request, const OptimizeResult& r) {
  char buffer[512];
  const double change = r.motion_blocks_in ? 100.0 * (double(r.motion_blocks_out) / double(r.motion_blocks_in) - 1.0) : 0;
  std::string deviation = "not checked";
  if (r.deviation) {
    char d[96];
    std::snprintf(d, sizeof d, "largest deviation %.4f mm (band %.4g)", r.deviation->largest(), request.optimizer.tolerance_mm);
    deviation = d;
  }
  std::snprintf(buffer, sizeof buffer,
                "optimize: %llu -> %llu motion blocks (%+.1f%%), %llu -> %llu commands, %llu arcs, %llu lines merged, %llu loops, %s, %.2f s",
                static_cast<unsigned long long>(r.motion_blocks_in), static_cast<unsigned long long>(r.motion_blocks_out),
                change, static_cast<unsigned long long>(r.commands_in), static_cast<unsigned long long>(r.commands_out),
                static_cast<unsigned long long>(r.stats.arcs), static_cast<unsigned long long>(r.stats.lines_merged),
                static_cast<unsigned long long>(r.loops.loops), deviation.c_str(), r.optimize_seconds);
  return buffer;
}

}  // namespace ncbridge::toolpath_optimizer
