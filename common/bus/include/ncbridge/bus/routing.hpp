#pragma once
// Which job inputs go to one worker only, and how: a job's samples on a routed topic are
// published in the partition of the worker of the reading stage that owns the job (rendezvous
// hashing over the stage's live workers when the job is first written), and each worker reads
// only its own partition. Every other topic (results, status, workers, a controller's blocks)
// stays in the default partition, read by everyone; the statuses that end a job (ERROR, the
// step writer's DONE, a client's DELIVERED) are also published in kJobOverPartition, the only
// statuses a worker reads (a worker need not hear every stage's RUNNING, PROGRESS and DONE of
// every job: at many workers that traffic cost more than the jobs).
#include <optional>
#include <string>
#include <string_view>

#include "ncbridge/bus/topics.hpp"

namespace ncbridge::bus {

inline constexpr std::string_view kJobOverPartition = "ncbridge.over";

// The stage that reads a routed topic; nullopt for a topic every reader gets whole.
std::optional<std::string_view> routed_to(Topic topic);

// The DDS partition a worker reads its jobs from. Cyclone matches partition names with the
// wildcards * and ?, so those (and the escape character %) are %-escaped in the worker id.
std::string worker_partition(std::string_view stage, std::string_view worker_id);

}  // namespace ncbridge::bus
