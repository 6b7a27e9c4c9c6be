#include "ncbridge/bus/rendezvous.hpp"

#include <algorithm>
#include <numeric>

namespace ncbridge::bus {
namespace {

constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ull;
constexpr std::uint64_t kFnvPrime = 0x100000001b3ull;

std::uint64_t fnv1a(std::uint64_t h, std::string_view bytes) {
  for (const char c : bytes) {
    h ^= static_cast<std::uint8_t>(c);
    h *= kFnvPrime;
  }
  return h;
}

// Spreads FNV's weak low-order mixing over all 64 bits (the splitmix64 finalizer constants).
std::uint64_t finalize(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// True when worker a outranks worker b for a job.
bool outranks(std::uint64_t score_a, std::string_view a, std::uint64_t score_b, std::string_view b) {
  return score_a != score_b ? score_a > score_b : a < b;
}

}  // namespace

std::uint64_t rendezvous_score(std::string_view job_id, std::string_view worker_id) {
  // The length prefix keeps ("ab","c") and ("a","bc") apart.
  std::uint64_t h = fnv1a(kFnvOffset, worker_id);
  h ^= worker_id.size();
  h *= kFnvPrime;
  return finalize(fnv1a(h, job_id));
}

std::optional<std::size_t> rendezvous_owner(std::string_view job_id, std::span<const std::string> workers) {
  std::optional<std::size_t> best;
  std::uint64_t best_score = 0;
  for (std::size_t i = 0; i < workers.size(); ++i) {
    const std::uint64_t s = rendezvous_score(job_id, workers[i]);
    if (!best || outranks(s, workers[i], best_score, workers[*best])) {
      best = i;
      best_score = s;
    }
  }
  return best;
}

std::vector<std::size_t> rendezvous_ranking(std::string_view job_id, std::span<const std::string> workers) {
  std::vector<std::uint64_t> scores(workers.size());
  for (std::size_t i = 0; i < workers.size(); ++i) scores[i] = rendezvous_score(job_id, workers[i]);
  std::vector<std::size_t> order(workers.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return outranks(scores[a], workers[a], scores[b], workers[b]); });
  return order;
}

}  // namespace ncbridge::bus
