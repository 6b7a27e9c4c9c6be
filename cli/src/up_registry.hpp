#pragma once
// Where `ncbridge up` runs, for the commands on the same machine that talk to it (submit, status,
// fetch, cancel, controller-sim, capture, down): one record per running `up`, per user, in
//   $XDG_RUNTIME_DIR/ncbridge/up-DOMAIN.json      (else ~/.local/state/ncbridge/)
// with its process id (and the process's start time, so a pid the system gave to another
// process since is not taken for it), its DDS domain and Cyclone configuration, and its step
// writers' --output-dir. `up` writes it when its services start and removes it when it stops; a
// record whose process is gone (up was killed) is ignored and removed by whoever reads it.
// docs/cli.md ("Finding the services").
#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ncbridge::cli {

struct UpRecord {
  pid_t pid = 0;
  std::uint64_t start_time = 0;  // the process's start time (/proc/PID/stat, clock ticks after boot)
  std::uint32_t domain = 0;
  std::string cyclonedds_uri;
  std::string output_dir;  // empty: the step writers write to the bus only
  std::string log;         // `up --detach`: its log file
  int workers = 1;
};

// The folder of the records (not created).
std::filesystem::path up_registry_directory();

// The start time of a running process (not a zombie), or nothing.
std::optional<std::uint64_t> process_start_time(pid_t pid);

// Is the record's process still the `up` that wrote it?
bool is_live(const UpRecord& record);

// The records of the `up`s that run, by domain; stale ones are removed.
std::vector<UpRecord> live_up_records();
std::optional<UpRecord> live_up_record(std::uint32_t domain);

// Written whole (atomically); the folder is made (mode 0700) when missing.
void write_up_record(const UpRecord& record);
void remove_up_record(std::uint32_t domain);

// Where `up` keeps the Cyclone configuration it makes for the domain.
std::filesystem::path up_generated_config(std::uint32_t domain);

}  // namespace ncbridge::cli
