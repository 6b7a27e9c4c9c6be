// bus_throughput: canonical batches over loopback DDS between two processes, at several batch
// sizes, like Cyclone's throughput example. The parent publishes a synthetic canonical stream
// (encode + write); a forked subscriber takes and decodes every batch and reports the calls it
// got. Prints samples/s, calls/s and MB/s of payload per batch size.
//
//   bus_throughput [--calls N] [--domain D] [--batches 64,256,1024,4096]
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ncbridge/bus/canonical_batcher.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/writer.hpp"

using namespace ncbridge;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

namespace {

// A plausible milling stream: mostly feeds and arcs, some rapids, a tool change now and then.
canonical::Call synthetic_call(std::size_t i) {
  const double t = static_cast<double>(i) * 0.01;
  canonical::Call c{canonical::StraightFeed{{t, 2 * t, -1, 0, 0, 0, 0, 0, 0}}, {0, static_cast<std::uint32_t>(i / 2 + 1), -1}, std::nullopt};
  if (i % 7 == 3) c.data = canonical::ArcFeed{t + 1, t, t + 0.5, t, 1, -1, 0, 0, 0, 0, 0, 0};
  if (i % 50 == 0) c.data = canonical::StraightTraverse{{t, t, 5, 0, 0, 0, 0, 0, 0}};
  if (i % 5000 == 0) c.data = canonical::ChangeTool{static_cast<int>(i / 5000 % 20)};
  return c;
}

struct Run {
  std::size_t per_batch;
  std::uint64_t batches = 0;
  std::uint64_t bytes = 0;
  double seconds = 0;
  double encode_seconds = 0;  // the same stream encoded with nowhere to go
};

double encode_only(const std::vector<canonical::Call>& stream, std::size_t per_batch) {
  std::uint64_t sink = 0;
  bus::CanonicalBatcher batcher("encode-only", per_batch, [&](const bus::Envelope& e) { sink += e.payload.size(); });
  const auto start = Clock::now();
  for (const canonical::Call& c : stream) batcher.call(c);
  batcher.end();
  const double s = std::chrono::duration<double>(Clock::now() - start).count();
  return sink > 0 ? s : 0;
}

// The subscriber: takes until it has seen the last batch of every run; prints the calls it got.
int subscribe(const bus::BusConfig& config, std::size_t runs) {
  bus::Participant participant(config);
  bus::Reader reader(participant, bus::Topic::Canonical);
  std::size_t finished = 0;
  std::uint64_t calls = 0;
  const auto deadline = Clock::now() + 300s;
  while (finished < runs && Clock::now() < deadline) {
    for (const bus::Received& r : reader.take(200ms, 1024)) {
      if (!r.has_data) continue;
      calls += canonical::decode_batch(r.envelope.payload).calls.size();
      if (r.envelope.last) ++finished;
    }
  }
  std::printf("%llu\n", static_cast<unsigned long long>(calls));
  std::fflush(stdout);
  return finished == runs ? 0 : 1;
}

std::vector<std::size_t> parse_list(const std::string& s) {
  std::vector<std::size_t> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(static_cast<std::size_t>(std::stoul(item)));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t calls = 1'000'000;
  std::uint32_t domain = 1 + static_cast<std::uint32_t>(getpid()) % 200;
  std::vector<std::size_t> sizes{16, 64, 256, 1024, 4096};
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--calls") calls = std::stoul(argv[i + 1]);
    else if (a == "--domain") domain = static_cast<std::uint32_t>(std::stoul(argv[i + 1]));
    else if (a == "--batches") sizes = parse_list(argv[i + 1]);
  }
  const auto config_file = std::filesystem::temp_directory_path() / ("ncbridge-bus-throughput-" + std::to_string(getpid()) + ".xml");
  std::ofstream(config_file) << bus::loopback_config_xml();
  const bus::BusConfig config{domain, "file://" + config_file.string()};

  int to_parent[2];
  if (pipe(to_parent) != 0) return 1;
  const pid_t child = fork();
  if (child == 0) {
    close(to_parent[0]);
    dup2(to_parent[1], STDOUT_FILENO);
    std::_Exit(subscribe(config, sizes.size()));
  }
  close(to_parent[1]);

  std::vector<Run> runs;
  {
    bus::Participant participant(config);
    bus::Writer writer(participant, bus::Topic::Canonical);
    if (!writer.wait_for_readers(1, 30s)) {
      std::fprintf(stderr, "bus_throughput: subscriber did not appear\n");
      return 1;
    }
    std::vector<canonical::Call> stream;
    stream.reserve(calls);
    for (std::size_t i = 0; i < calls; ++i) stream.push_back(synthetic_call(i));
    for (std::size_t per_batch : sizes) {
      Run run{per_batch};
      run.encode_seconds = encode_only(stream, per_batch);
      const std::string job = "throughput-" + std::to_string(per_batch);
      bus::CanonicalBatcher batcher(job, per_batch, [&](const bus::Envelope& e) {
        writer.write(e);
        ++run.batches;
        run.bytes += e.payload.size();
      });
      const auto start = Clock::now();
      batcher.source_file(0, "synthetic.ngc");
      for (const canonical::Call& c : stream) batcher.call(c);
      batcher.end();
      if (!writer.wait_for_acks(120s)) std::fprintf(stderr, "bus_throughput: acks timed out\n");
      run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      writer.unregister(job, "");
      runs.push_back(run);
    }
    // Stay matched until the subscriber has taken everything.
    std::string received;
    char buf[64];
    ssize_t n;
    while ((n = read(to_parent[0], buf, sizeof buf)) > 0) received.append(buf, static_cast<std::size_t>(n));
    int status = 0;
    waitpid(child, &status, 0);
    std::filesystem::remove(config_file);
    const unsigned long long got = std::strtoull(received.c_str(), nullptr, 10);
    std::printf("canonical batches over loopback DDS (2 processes, RELIABLE, transient-local), %zu calls a run\n", calls);
    std::printf("%11s %8s %11s %10s %10s %8s %16s\n", "calls/batch", "batches", "bytes/batch", "samples/s", "calls/s",
                "MB/s", "encode-only c/s");
    for (const Run& r : runs) {
      std::printf("%11zu %8llu %11.0f %10.0f %10.0f %8.1f %16.0f\n", r.per_batch,
                  static_cast<unsigned long long>(r.batches), static_cast<double>(r.bytes) / static_cast<double>(r.batches),
                  static_cast<double>(r.batches) / r.seconds, static_cast<double>(calls) / r.seconds,
                  static_cast<double>(r.bytes) / r.seconds / 1e6, static_cast<double>(calls) / r.encode_seconds);
    }
    std::printf("subscriber decoded %llu of %zu calls%s\n", got, calls * sizes.size(),
                got == calls * sizes.size() && WIFEXITED(status) && WEXITSTATUS(status) == 0 ? "" : "  <-- MISMATCH");
    return got == calls * sizes.size() ? 0 : 1;
  }
}
