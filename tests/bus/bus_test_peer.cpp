// A second process for the DDS tests (tests/bus/bus_pubsub_test.cpp). Every mode ends by
// itself within its time limit, so a failed test never leaves it behind.
//   bus_test_peer publish DOMAIN CONFIG_URI JOB CALLS PER_BATCH   publish a job's canonical stream
//   bus_test_peer worker DOMAIN CONFIG_URI STAGE WORKER_ID SECONDS announce a worker, then wait
//                                                                 (SIGTERM: leave cleanly)
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "canonical_samples.hpp"
#include "ncbridge/bus/canonical_batcher.hpp"
#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/worker_presence.hpp"
#include "ncbridge/bus/writer.hpp"

using namespace ncbridge;
using namespace std::chrono_literals;

namespace {

volatile std::sig_atomic_t g_stop = 0;  // set by the SIGTERM handler: the only way to reach it
void on_term(int) { g_stop = 1; }

bus::BusConfig config(const char* domain, const char* uri) {
  return {static_cast<std::uint32_t>(std::atoi(domain)), uri};
}

int publish(char** argv) {
  bus::Participant participant(config(argv[2], argv[3]));
  bus::Writer writer(participant, bus::Topic::Canonical);
  if (!writer.wait_for_readers(1, 20s)) {
    std::fprintf(stderr, "bus_test_peer: no reader matched\n");
    return 2;
  }
  const auto calls = static_cast<std::size_t>(std::atol(argv[5]));
  bus::CanonicalBatcher batcher(argv[4], static_cast<std::size_t>(std::atol(argv[6])),
                                [&](const bus::Envelope& e) { writer.write(e); });
  batcher.source_file(0, "peer.ngc");
  for (std::size_t i = 0; i < calls; ++i) batcher.call(test::sample_call(i));
  batcher.end();
  return writer.wait_for_acks(20s) ? 0 : 3;
}

int worker(char** argv) {
  std::signal(SIGTERM, on_term);
  bus::Participant participant(config(argv[2], argv[3]));
  wire::WorkerInfo info = bus::this_process_worker(argv[4]);
  info.worker_id = argv[5];
  bus::WorkerPresence presence(participant, info);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(std::atoi(argv[6]));
  while (g_stop == 0 && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(10ms);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "publish" && argc == 7) return publish(argv);
    if (mode == "worker" && argc == 7) return worker(argv);
    std::fprintf(stderr, "usage: bus_test_peer publish|worker ...\n");
    return 64;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bus_test_peer: %s\n", e.what());
    return 1;
  }
}
