// Read and write throughput of the Part 21 layer (MB/s of file text), on the largest Part 21 file
// of the shared corpus, and the schema check on the largest ISO 14649 file.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/part21_writer.hpp"
#include "ncbridge/step_writer/schema_check.hpp"

namespace fs = std::filesystem;
using namespace ncbridge::step_writer;

namespace {

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const fs::path& largest_part21_file() {
  static const fs::path largest = [] {
    fs::path best;
    std::uintmax_t best_size = 0;
    for (const auto& e : fs::recursive_directory_iterator(fs::path(NCBRIDGE_SHARED_DIR) / "corpus")) {
      auto ext = e.path().extension();
      if (e.is_regular_file() && (ext == ".stp" || ext == ".step") && e.file_size() > best_size) {
        best = e.path();
        best_size = e.file_size();
      }
    }
    return best;
  }();
  return largest;
}

void BM_ReadPart21(benchmark::State& state) {
  const std::string text = slurp(largest_part21_file());
  state.SetLabel(largest_part21_file().filename().string());
  for (auto _ : state) {
    auto result = part21::read_part21(text, "bench.stp");
    benchmark::DoNotOptimize(result.graph.size());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ReadPart21)->Unit(benchmark::kMillisecond);

void BM_WritePart21(benchmark::State& state) {
  const auto graph = part21::read_part21(slurp(largest_part21_file()), "bench.stp").graph;
  part21::WriteOptions options;
  options.unix_time = 0;
  std::size_t bytes = 0;
  for (auto _ : state) {
    std::string text = part21::write_part21(graph, options);
    bytes = text.size();
    benchmark::DoNotOptimize(text.data());
  }
  state.SetLabel(largest_part21_file().filename().string());
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_WritePart21)->Unit(benchmark::kMillisecond);

void BM_CheckIso14649(benchmark::State& state) {
  const fs::path file = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/stepnc/nist_ex1E.stp";
  const std::string text = slurp(file);
  const auto graph = part21::read_part21(text, "bench.stp").graph;
  const auto schema =
      express::Schema::parse_file(fs::path(NCBRIDGE_SHARED_DIR) / "reference/iso14649/combined_schema_iso14649_only.exp");
  for (auto _ : state) benchmark::DoNotOptimize(check_instances(graph, schema).size());
  state.SetLabel("nist_ex1E.stp");
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
  state.counters["instances/s"] =
      benchmark::Counter(static_cast<double>(graph.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_CheckIso14649)->Unit(benchmark::kMillisecond);

void BM_ParseIso14649Schema(benchmark::State& state) {
  const std::string text =
      slurp(fs::path(NCBRIDGE_SHARED_DIR) / "reference/iso14649/combined_schema_iso14649_only.exp");
  for (auto _ : state) benchmark::DoNotOptimize(express::Schema::parse(text, "schema.exp").entities().size());
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ParseIso14649Schema)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
