#include "up_registry.hpp"

#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

namespace ncbridge::cli {

namespace fs = std::filesystem;

namespace {

fs::path record_path(std::uint32_t domain) { return up_registry_directory() / ("up-" + std::to_string(domain) + ".json"); }

std::optional<UpRecord> read_record(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    UpRecord r;
    r.pid = j.at("pid").get<pid_t>();
    r.start_time = j.at("start_time").get<std::uint64_t>();
    r.domain = j.at("domain").get<std::uint32_t>();
    r.cyclonedds_uri = j.at("cyclonedds_uri").get<std::string>();
    r.output_dir = j.value("output_dir", "");
    r.log = j.value("log", "");
    r.workers = j.value("workers", 1);
    return r;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // half a record (cannot be: written atomically) or not ours: ignored
  }
}

}  // namespace

fs::path up_registry_directory() {
  if (const char* runtime = std::getenv("XDG_RUNTIME_DIR"); runtime != nullptr && *runtime == '/')
    return fs::path(runtime) / "ncbridge";
  if (const char* home = std::getenv("HOME"); home != nullptr && *home == '/')
    return fs::path(home) / ".local" / "state" / "ncbridge";
  return fs::temp_directory_path() / ("ncbridge-" + std::to_string(getuid()));
}

std::optional<std::uint64_t> process_start_time(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!in || !std::getline(in, stat)) return std::nullopt;
  // "PID (COMM) STATE PPID ..." where COMM may hold spaces and parentheses: fields after the last ')'.
  const auto close = stat.rfind(')');
  if (close == std::string::npos) return std::nullopt;
  std::istringstream fields(stat.substr(close + 1));
  std::string state;
  fields >> state;
  if (state == "Z" || state == "X") return std::nullopt;  // exited, not yet reaped
  std::string skip;
  for (int field = 4; field < 22; ++field) fields >> skip;  // ppid .. priority, nice, ..., itrealvalue
  std::uint64_t start = 0;
  if (!(fields >> start)) return std::nullopt;
  return start;
}

bool is_live(const UpRecord& record) {
  const auto start = process_start_time(record.pid);
  return start && *start == record.start_time;
}

std::vector<UpRecord> live_up_records() {
  std::vector<UpRecord> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(up_registry_directory(), ec)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with("up-") || !name.ends_with(".json")) continue;
    const std::optional<UpRecord> r = read_record(entry.path());
    if (r && is_live(*r)) {
      out.push_back(*r);
    } else if (r) {
      fs::remove(entry.path(), ec);
      fs::remove(up_generated_config(r->domain), ec);
    }
  }
  std::sort(out.begin(), out.end(), [](const UpRecord& a, const UpRecord& b) { return a.domain < b.domain; });
  return out;
}

std::optional<UpRecord> live_up_record(std::uint32_t domain) {
  for (UpRecord& r : live_up_records()) {
    if (r.domain == domain) return std::move(r);
  }
  return std::nullopt;
}

void write_up_record(const UpRecord& record) {
  const fs::path dir = up_registry_directory();
  fs::create_directories(dir);
  fs::permissions(dir, fs::perms::owner_all, fs::perm_options::replace);
  const nlohmann::json j{{"pid", record.pid},
                         {"start_time", record.start_time},
                         {"domain", record.domain},
                         {"cyclonedds_uri", record.cyclonedds_uri},
                         {"output_dir", record.output_dir},
                         {"log", record.log},
                         {"workers", record.workers}};
  const fs::path path = record_path(record.domain);
  const fs::path temporary = path.string() + ".tmp-" + std::to_string(getpid());
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << j.dump(2) << '\n';
    if (!out.flush()) throw std::system_error(errno, std::generic_category(), "cannot write " + temporary.string());
  }
  fs::rename(temporary, path);
}

void remove_up_record(std::uint32_t domain) {
  std::error_code ec;
  fs::remove(record_path(domain), ec);
}

fs::path up_generated_config(std::uint32_t domain) {
  return up_registry_directory() / ("up-" + std::to_string(domain) + "-cyclonedds.xml");
}

}  // namespace ncbridge::cli
