#pragma once
// Work sharing without a broker: every worker of a stage computes the same owner for a job
// from the same list of live workers (highest random weight / rendezvous hashing). When a
// worker leaves, only its jobs move; each to the survivor that ranked second for it.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ncbridge::bus {

// Stable across processes, hosts and compilers (FNV-1a then a 64-bit finalizer).
std::uint64_t rendezvous_score(std::string_view job_id, std::string_view worker_id);

// Index in `workers` of the job's owner: the highest score, ties to the smaller worker id.
// nullopt when there are no workers. The order of `workers` does not matter.
std::optional<std::size_t> rendezvous_owner(std::string_view job_id, std::span<const std::string> workers);

// All workers, best first: who takes the job over if the owner dies, and after it.
std::vector<std::size_t> rendezvous_ranking(std::string_view job_id, std::span<const std::string> workers);

}  // namespace ncbridge::bus
