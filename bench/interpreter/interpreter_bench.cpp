// Micro-benchmarks of the RS274/NGC interpreter library: programs held in memory, calls
// delivered to a sink that only counts them (bench/interpreter/run.sh times the whole command).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/interpreter/canon_printer.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "program_generator.hpp"

namespace {

class CountingSink final : public ncbridge::canonical::Sink {
 public:
  void call(const ncbridge::canonical::Call&) override { ++calls; }
  long calls = 0;
};

ncbridge::interpreter::Options tool_options() {
  ncbridge::setup::Tool tool;
  tool.number = 1;
  tool.pocket = 1;
  tool.diameter = 6;
  tool.length = 50;
  ncbridge::interpreter::Options options;
  options.tools = ncbridge::setup::ToolList({tool});
  return options;
}

void interpret(benchmark::State& state, const std::string& program, long lines) {
  const auto options = tool_options();
  long calls = 0;
  for (auto _ : state) {
    CountingSink sink;
    ncbridge::interpreter::interpret_text(program, "bench.ngc", options, sink);
    calls = sink.calls;
    benchmark::DoNotOptimize(calls);
  }
  state.SetItemsProcessed(state.iterations() * lines);  // items = program lines
  state.SetBytesProcessed(state.iterations() * static_cast<long>(program.size()));
  state.counters["calls"] = static_cast<double>(calls);
}

std::string repeated(const std::string& header, const std::string& body, long times) {
  std::string program = header;
  for (long i = 0; i < times; ++i) program += body;
  return program + "M2\n";
}

// The whole-program benchmark's mix: moves, arcs, comments, parameters, expressions.
void BM_GeneratedProgram(benchmark::State& state) {
  const long lines = state.range(0);
  interpret(state, ncbridge::bench::generate_ngc_program(lines, 1), lines);
}
BENCHMARK(BM_GeneratedProgram)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_StraightFeeds(benchmark::State& state) {
  const std::string program = repeated("G21 G90 G17 F1000\n", "G1 X10.5 Y20.25 Z-1\nG1 X0 Y0 Z-1.5\n", 50000);
  interpret(state, program, 100002);
}
BENCHMARK(BM_StraightFeeds)->Unit(benchmark::kMillisecond);

void BM_Arcs(benchmark::State& state) {
  const std::string program = repeated("G21 G90 G17 F1000\nG0 X10 Y0\n", "G3 X-10 Y0 I-10 J0\nG3 X10 Y0 R10\n", 50000);
  interpret(state, program, 100003);
}
BENCHMARK(BM_Arcs)->Unit(benchmark::kMillisecond);

void BM_Expressions(benchmark::State& state) {
  const std::string program = repeated(
      "G21 G90 F1000\n#1 = 0\n",
      "#1 = [#1 + 0.001]\nG1 X[SIN[#1 * 30] * 10 + COS[#1] ** 2] Y[ATAN[#1]/[1] + SQRT[ABS[#1]] MOD 3]\n", 50000);
  interpret(state, program, 100003);
}
BENCHMARK(BM_Expressions)->Unit(benchmark::kMillisecond);

void BM_WhileLoop(benchmark::State& state) {
  const std::string program =
      "G21 G90 F1000\n#1 = 0\no1 while [#1 LT 100000]\n  #1 = [#1 + 1]\n  G1 X[#1 MOD 100]\no1 endwhile\nM2\n";
  interpret(state, program, 3 * 100000);  // lines executed, not lines in the file
}
BENCHMARK(BM_WhileLoop)->Unit(benchmark::kMillisecond);

void BM_CannedCycles(benchmark::State& state) {
  const std::string program = repeated("G21 G90 G17 F200\nT1 M6 G43 H1\nG0 Z10\n",
                                       "G98 G83 X5 Y5 Z-10 R2 Q2\nG99 G81 X10 Y5 Z-3 R1\nG80\n", 20000);
  interpret(state, program, 60004);
}
BENCHMARK(BM_CannedCycles)->Unit(benchmark::kMillisecond);

// The same generated program printed in rs274's format to /dev/null: interpretation + printing.
void BM_GeneratedProgramPrinted(benchmark::State& state) {
  const long lines = 100000;
  const std::string program = ncbridge::bench::generate_ngc_program(lines, 1);
  const auto options = tool_options();
  std::FILE* null_out = std::fopen("/dev/null", "w");
  for (auto _ : state) {
    ncbridge::interpreter::CanonPrinter printer(null_out);
    ncbridge::interpreter::interpret_text(program, "bench.ngc", options, printer);
  }
  std::fclose(null_out);
  state.SetItemsProcessed(state.iterations() * lines);
  state.SetBytesProcessed(state.iterations() * static_cast<long>(program.size()));
}
BENCHMARK(BM_GeneratedProgramPrinted)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
