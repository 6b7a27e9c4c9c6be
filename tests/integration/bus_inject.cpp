// Test tool: publishes bad samples on the bus, as a broken or hostile peer would, for
// bad_input_test.sh. The bus is CYCLONEDDS_URI / NCBRIDGE_DDS_DOMAIN's.
//   bus_inject truncated-job JOB       half of a valid Job's bytes on the programs topic
//   bus_inject truncated-batch JOB     a valid job context, then a cut CanonicalBatch (canonical)
//   bus_inject wrong-type JOB TOPIC    a JobStatus where TOPIC (workingsteps|features) wants a model
// and, as a late reader, for results_test.sh:
//   bus_inject results-of JOB          prints how many pieces of JOB's Part 21 file the bus still
//                                      holds ("JOB: N pieces[, last]"), listening for 2 s
#include <chrono>
#include <cstdio>
#include <string>
#include <string_view>

#include "ncbridge/bus/participant.hpp"
#include "ncbridge/bus/reader.hpp"
#include "ncbridge/bus/routed_writer.hpp"
#include "ncbridge/canonical/proto_codec.hpp"
#include "ncbridge/service/canonical_stream.hpp"
#include "ncbridge/wire/job.hpp"
#include "ncbridge/wire/status.hpp"

using namespace ncbridge;

namespace {

wire::Job small_job(const std::string& id) {
  wire::Job job;
  job.job_id = id;
  job.file_name = "injected.ngc";
  job.program_text = "G0 X1 Y2 Z3\nG1 X10 F100\nM2\n";
  job.output_name = id + ".stp";
  return job;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bus_inject truncated-job|truncated-batch|wrong-type|results-of JOB [TOPIC]\n");
    return 2;
  }
  const std::string mode = argv[1];
  const std::string job_id = argv[2];
  bus::Participant participant(bus::config_from_environment());
  if (mode == "results-of") {
    bus::Reader part21(participant, bus::Topic::Part21);
    std::size_t pieces = 0;
    bool last = false;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (std::chrono::steady_clock::now() < end) {
      for (const bus::Received& r : part21.take(std::chrono::milliseconds(100))) {
        if (!r.has_data || r.envelope.key != job_id) continue;
        ++pieces;
        last = last || r.envelope.last;
      }
    }
    std::printf("%s: %zu pieces%s\n", job_id.c_str(), pieces, last ? ", last" : "");
    return 0;
  }
  bus::Topic topic = bus::Topic::Programs;
  if (mode == "truncated-batch") topic = bus::Topic::Canonical;
  if (mode == "wrong-type") topic = argc > 3 && std::string_view(argv[3]) == "features" ? bus::Topic::Features
                                                                                        : bus::Topic::Workingsteps;
  bus::RoutedWriter writer(participant, topic);
  if (!writer.wait_for_readers(1, std::chrono::seconds(10))) {
    std::fprintf(stderr, "bus_inject: no reader of the topic\n");
    return 3;
  }
  if (mode == "truncated-job") {
    const std::string bytes = wire::encode_job(small_job(job_id));
    writer.write(job_id, "", 0, 0, true, bytes.substr(0, bytes.size() / 2));
  } else if (mode == "truncated-batch") {
    wire::Job context = small_job(job_id);
    context.program_text.clear();
    writer.write(job_id, "", 0, service::kJobContext, false, wire::encode_job(context));
    const canonical::Call calls[] = {{canonical::StraightTraverse{{1, 2, 3}}, {0, 1, -1, 0}, std::nullopt},
                                     {canonical::StraightFeed{{10, 2, 3}}, {0, 2, -1, 0}, std::nullopt}};
    const std::string batch = canonical::encode_batch({job_id, 0, {}, calls, true});
    writer.write(job_id, "", 1, service::kCanonicalBatch, true, batch.substr(0, batch.size() - 3));
  } else if (mode == "wrong-type") {
    wire::JobStatus status;
    status.job_id = job_id;
    status.stage = "impostor";
    status.message = "not a model";
    writer.write(job_id, "", 0, 0, true, wire::encode_status(status));
  } else {
    std::fprintf(stderr, "bus_inject: unknown mode %s\n", mode.c_str());
    return 2;
  }
  return writer.wait_for_acks(std::chrono::seconds(10)) ? 0 : 4;
}
