#include "ncbridge/bus/worker_directory.hpp"

namespace ncbridge::bus {

WorkerDirectory::WorkerDirectory(Participant& participant) : reader_(participant, Topic::Workers) {}

bool WorkerDirectory::poll(std::chrono::milliseconds timeout) {
  bool changed = false;
  for (const Received& r : reader_.take(timeout)) changed = tracker_.apply(r) || changed;
  return changed;
}

}  // namespace ncbridge::bus
