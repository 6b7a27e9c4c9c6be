#include "client_bus.hpp"

#include <cstdlib>
#include <string>

#include "errors.hpp"

namespace ncbridge::cli {

ClientBus client_bus(std::optional<std::uint32_t> domain_option) {
  ClientBus bus;
  bus.config = bus::config_from_environment();  // NCBRIDGE_DDS_DOMAIN checked here
  const char* env_domain = std::getenv("NCBRIDGE_DDS_DOMAIN");
  const bool domain_given = domain_option || (env_domain != nullptr && *env_domain != '\0');
  if (domain_option) bus.config.domain_id = *domain_option;
  if (domain_given) {
    bus.up = live_up_record(bus.config.domain_id);
  } else {
    std::vector<UpRecord> running = live_up_records();
    if (running.size() > 1) {
      std::string domains;
      for (const UpRecord& r : running) domains += (domains.empty() ? "" : ", ") + std::to_string(r.domain);
      throw UsageError("several `ncbridge up` run on this machine (DDS domains " + domains + "): say which with --domain");
    }
    if (running.size() == 1) {
      bus.up = running.front();
      bus.config.domain_id = bus.up->domain;
    }
  }
  const char* env_uri = std::getenv("CYCLONEDDS_URI");
  if ((env_uri == nullptr || *env_uri == '\0') && bus.up) bus.config.cyclonedds_uri = bus.up->cyclonedds_uri;
  return bus;
}

std::string no_service_message(const ClientBus& bus, std::string_view service) {
  std::string text = "no " + std::string(service) + " service on DDS domain " + std::to_string(bus.config.domain_id);
  if (bus.up) return text + " (`ncbridge up` runs there, pid " + std::to_string(bus.up->pid) + ", but its services do not answer)";
  return text + " (no `ncbridge up` runs for this user on this machine: start one, or give the services' --domain and CYCLONEDDS_URI)";
}

}  // namespace ncbridge::cli
