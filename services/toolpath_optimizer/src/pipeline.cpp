// optimize(): front-end -> optimizer -> writer, with the checker on both ends (pipeline.hpp).
#include "ncbridge/toolpath_optimizer/pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "ncbridge/common/error.hpp"
#include "ncbridge/gcode_writer/program_writer.hpp"
#include "ncbridge/toolpath_optimizer/block_count.hpp"
#include "ncbridge/toolpath_optimizer/canonical_bridge.hpp"
#include "ncbridge/toolpath_optimizer/printer_writer.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

using Clock = std::chrono::steady_clock;

// Hands each element to the next stage, giving its path to the checker on the way when asked.
class Tee final : public ElementSink {
 public:
  Tee(ElementSink& next, DeviationChecker* checker) : next_(next), checker_(checker) {}
  void element(Element&& e) override {
    if (checker_ && std::holds_alternative<Motion>(e.item)) {
      path_pieces(e, [this](const PathPiece& p) { checker_->input(p); });
    }
    next_.element(std::move(e));
  }
  void end() override { next_.end(); }

 private:
  ElementSink& next_;
  DeviationChecker* checker_;
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

// Elements to the gcode_writer: loops as its repeat construct.
class CncOutput final : public ElementSink {
 public:
  explicit CncOutput(gcode_writer::ProgramWriter& writer) : writer_(writer) {}
  void element(Element&& e) override {
    if (const auto* loop = std::get_if<Loop>(&e.item)) {
      writer_.begin_repeat(loop->count, loop->z_shift);
      for (const auto& inner : loop->body) to_canonical(inner, writer_);
      writer_.end_repeat();
      return;
    }
    to_canonical(e, writer_);
  }
  void end() override { writer_.end(); }

 private:
  gcode_writer::ProgramWriter& writer_;
};

interpreter::Dialect to_interpreter(gcode_writer::Dialect d) {
  switch (d) {
    case gcode_writer::Dialect::Fanuc: return interpreter::Dialect::Fanuc;
    case gcode_writer::Dialect::Mach3: return interpreter::Dialect::Mach3;
    case gcode_writer::Dialect::Siemens840D: return interpreter::Dialect::Siemens840D;
    case gcode_writer::Dialect::Heidenhain: return interpreter::Dialect::Heidenhain;
    default: return interpreter::Dialect::Rs274Ngc;
  }
}

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
  if (!cnc && request.output == OutputFormat::Cnc) {
    throw InputError({request.input.string(), 0, 0}, "printer G-code is written as printer G-code or KRL, not in a CNC dialect");
  }
  if (request.loops && request.output == OutputFormat::PrinterGcode) {
    throw InputError({request.input.string(), 0, 0}, "printer G-code has no loop construct: --loops needs --to krl or a CNC dialect");
  }
  const bool krl = request.output == OutputFormat::Krl;
  const bool dialect_out = request.output == OutputFormat::Cnc;
  OptimizerOptions optimizer_options = request.optimizer;
  KrlOptions krl_options = request.krl;
  LoopOptions loop_options = request.loop;
  if (dialect_out) {
    // What the writer rounds: coordinates and centres to its decimals (one more in inches).
    const int decimals = request.writer.decimals.value_or(4);
    optimizer_options.margin_mm = std::max(optimizer_options.margin_mm, 3 * std::pow(10.0, -decimals));
    optimizer_options.centre_decimals = decimals;
    optimizer_options.true_arcs = true;
    // Heidenhain's CC/C are circles in the XY plane only.
    optimizer_options.xy_arcs_only = request.writer.dialect == gcode_writer::Dialect::Heidenhain;
    loop_options.motions_and_feeds_only = true;
  }
  if (krl) {
    // CIRC is a plane circle through an auxiliary point written with krl.decimals.
    optimizer_options.helical = false;
    optimizer_options.margin_mm = std::max(optimizer_options.margin_mm, 3 * std::pow(10.0, -krl_options.decimals));
    krl_options.extruder = !cnc;
    krl_options.approximation_mm = request.optimizer.tolerance_mm;
    if (krl_options.source.empty()) krl_options.source = request.input.filename().string();
  }

  // The checker takes both paths as they stream (printer output is read back as it is written,
  // so it holds only what the optimizer and the writer hold); KRL and CNC output are read back
  // whole at the end.
  DeviationOptions check_options;
  check_options.tolerance = request.optimizer.tolerance_mm;
  DeviationChecker checker(check_options);
  CheckerFeed output_path(checker, true);
  DeviationChecker* in_checker = request.check ? &checker : nullptr;
  Clock::duration check_time{};
  // The written text, read back by the output's own front-end: printer lines as they come, the
  // KRL program when it is whole.
  std::unique_ptr<PrinterReader> back;
  std::string krl_text;  // KRL or a CNC dialect: read back whole
  if (request.check && request.output == OutputFormat::PrinterGcode) back = std::make_unique<PrinterReader>(request.output_name, request.flavor, output_path);
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
  std::unique_ptr<gcode_writer::ProgramWriter> program_writer;
  BlockCounter out_blocks(request.writer.dialect == gcode_writer::Dialect::Heidenhain);
  if (dialect_out) {
    program_writer = std::make_unique<gcode_writer::ProgramWriter>(request.writer, [&](std::string_view chunk) {
      out_blocks.text(chunk);
      out_main(chunk);
    });
    writer = std::make_unique<CncOutput>(*program_writer);
  } else if (krl) {
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
    loops = std::make_unique<LoopDetector>(loop_options, *writer);
    after_optimizer = loops.get();
  }
  Optimizer optimizer(optimizer_options, *after_optimizer);
  Tee tee(optimizer, in_checker);
  Progress progress(tee, request.progress);
  if (cnc) {
    const BlockCounts in = count_file_blocks(request.input, request.cnc.dialect == interpreter::Dialect::Heidenhain);
    result.bytes_in = in.bytes;
    result.lines_in = in.lines;
    result.commands_in = in.commands;
    result.motion_blocks_in = in.motion_blocks;
    result.arcs_in = in.arcs;
    CanonicalFrontEnd front_end(progress, program_writer.get());
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
  } else if (krl_writer) {
    result.lines_out = krl_writer->lines();
    result.commands_out = krl_writer->commands();
    result.motion_blocks_out = krl_writer->motion_statements();
  } else {
    const BlockCounts out = out_blocks.finish();
    result.bytes_out = out.bytes;
    result.lines_out = out.lines;
    result.commands_out = out.commands;
    result.motion_blocks_out = out.motion_blocks;
  }
  result.stats = optimizer.stats();
  if (loops) result.loops = loops->stats();
  if (request.check) {
    const auto t = Clock::now();
    if (back) {
      back->finish();
    } else if (krl) {
      read_krl_text(krl_text, request.output_name, output_path);
    } else {
      interpreter::Options reading;
      reading.dialect = to_interpreter(request.writer.dialect);
      reading.tools = request.writer.tools;
      reading.require_program_end = false;
      CanonicalFrontEnd front_end(output_path);
      interpreter::interpret_text(krl_text, request.output_name, reading, front_end);
    }
    result.deviation = checker.finish();
    result.check_pieces_held = checker.most_held();
    check_time += Clock::now() - t;
    result.check_seconds = seconds(check_time);
    if (!result.deviation->passed(check_options.tolerance)) {
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
                "%llu -> %llu motion blocks (%+.1f%%), %llu -> %llu commands, %llu arcs, %llu lines merged, %llu loops, %s, %.2f s",
                static_cast<unsigned long long>(r.motion_blocks_in), static_cast<unsigned long long>(r.motion_blocks_out),
                change, static_cast<unsigned long long>(r.commands_in), static_cast<unsigned long long>(r.commands_out),
                static_cast<unsigned long long>(r.stats.arcs), static_cast<unsigned long long>(r.stats.lines_merged),
                static_cast<unsigned long long>(r.loops.loops), deviation.c_str(), r.optimize_seconds);
  return buffer;
}

}  // namespace ncbridge::toolpath_optimizer
