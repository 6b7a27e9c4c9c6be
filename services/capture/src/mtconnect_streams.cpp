#include "ncbridge/capture/mtconnect_streams.hpp"

#include <algorithm>
#include <charconv>
#include <pugixml.hpp>

#include "ncbridge/common/error.hpp"

namespace ncbridge::capture {
namespace {

[[noreturn]] void bad(const std::string& message) { throw InputError({"<mtconnect>", 0, 0}, message); }

std::uint64_t number(const pugi::xml_attribute& a, const char* what) {
  const char* text = a.value();
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text, text + std::char_traits<char>::length(text), v);
  if (ec != std::errc() || end == text || *end != '\0') bad(std::string("the ") + what + " is not a number: \"" + text + "\"");
  return v;
}

// An element name without its namespace prefix ("m:Execution" -> "Execution").
std::string_view local(const char* name) {
  std::string_view n = name;
  const std::size_t colon = n.find(':');
  return colon == std::string_view::npos ? n : n.substr(colon + 1);
}

}  // namespace

MtconnectStreams parse_mtconnect_streams(std::string_view xml) {
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(xml.data(), xml.size());
  if (!parsed) bad(std::string("not XML: ") + parsed.description() + " at byte " + std::to_string(parsed.offset));
  const pugi::xml_node root = doc.document_element();
  if (local(root.name()) == "MTConnectError") {
    std::string message = "the agent answered with an error:";
    for (const pugi::xpath_node& e : root.select_nodes("//*[local-name()='Error']")) {
      message += std::string(" ") + e.node().attribute("errorCode").value() + " (" + e.node().text().get() + ")";
    }
    bad(message);
  }
  if (local(root.name()) != "MTConnectStreams") bad("not an MTConnectStreams document (root <" + std::string(root.name()) + ">)");
  MtconnectStreams s;
  pugi::xml_node header;
  for (const pugi::xml_node& child : root.children()) {
    if (local(child.name()) == "Header") header = child;
  }
  if (!header) bad("MTConnectStreams without a Header");
  s.instance_id = number(header.attribute("instanceId"), "instanceId");
  s.first_sequence = number(header.attribute("firstSequence"), "firstSequence");
  s.next_sequence = number(header.attribute("nextSequence"), "nextSequence");
  s.last_sequence = number(header.attribute("lastSequence"), "lastSequence");
  for (const pugi::xpath_node& d : root.select_nodes("//*[local-name()='DeviceStream']")) {
    const std::string device = d.node().attribute("name").value();
    for (const pugi::xpath_node& o : d.node().select_nodes(".//*[@sequence]")) {
      MtconnectObservation obs;
      obs.sequence = number(o.node().attribute("sequence"), "sequence");
      obs.device = device;
      obs.name = std::string(local(o.node().name()));
      obs.sub_type = o.node().attribute("subType").value();
      obs.value = o.node().text().get();
      s.observations.push_back(std::move(obs));
    }
  }
  std::stable_sort(s.observations.begin(), s.observations.end(),
                   [](const MtconnectObservation& a, const MtconnectObservation& b) { return a.sequence < b.sequence; });
  return s;
}

}  // namespace ncbridge::capture
