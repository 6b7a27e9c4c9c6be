#include "ncbridge/bus/config.hpp"

#include <charconv>
#include <cstdlib>
#include <string_view>

#include "ncbridge/bus/bus_error.hpp"

namespace ncbridge::bus {

BusConfig config_from_environment() {
  BusConfig config;
  if (const char* domain = std::getenv("NCBRIDGE_DDS_DOMAIN"); domain != nullptr && *domain != '\0') {
    const std::string_view text(domain);
    std::uint32_t id = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), id);
    if (ec != std::errc() || end != text.data() + text.size() || id > 230)
      throw BusError("NCBRIDGE_DDS_DOMAIN must be a DDS domain id 0..230, not \"" + std::string(text) + "\"");
    config.domain_id = id;
  }
  return config;
}

std::string loopback_config_xml(std::chrono::milliseconds lease) {
  return "<CycloneDDS xmlns=\"https://cdds.io/config\"><Domain id=\"any\">"
         "<General><Interfaces><NetworkInterface name=\"lo\" multicast=\"true\"/></Interfaces>"
         "<MaxMessageSize>65000B</MaxMessageSize><FragmentSize>62000B</FragmentSize></General>"
         "<Discovery><LeaseDuration>" + std::to_string(lease.count()) + "ms</LeaseDuration></Discovery>"
         "<SharedMemory><Enable>false</Enable></SharedMemory>"
         "<Internal><Watermarks><WhcHigh>8MB</WhcHigh></Watermarks><HeartbeatInterval>10ms</HeartbeatInterval>"
         "<SocketReceiveBufferSize min=\"default\" max=\"8MB\"/><SocketSendBufferSize min=\"default\" max=\"8MB\"/>"
         "</Internal></Domain></CycloneDDS>";
}

}  // namespace ncbridge::bus
