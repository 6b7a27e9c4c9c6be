#pragma once
// Internal: the DDS topic entity of a Topic, with the one envelope type.
#include <string>
#include <string_view>

#include "dds_check.hpp"
#include "envelope.h"
#include "ncbridge/bus/topics.hpp"

namespace ncbridge::bus::detail {

inline dds_entity_t create_topic(dds_entity_t participant, Topic topic) {
  const std::string name(topic_name(topic));
  return check(dds_create_topic(participant, &ncbridge_bus_Envelope_desc, name.c_str(), nullptr, nullptr),
               "dds_create_topic");
}

// A publisher or subscriber in one partition, for a writer or reader that only its peers in
// that partition match.
inline dds_entity_t create_publisher(dds_entity_t participant, std::string_view partition) {
  const std::string name(partition);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_partition1(qos, name.c_str());
  const dds_entity_t publisher = dds_create_publisher(participant, qos, nullptr);
  dds_delete_qos(qos);
  return check(publisher, "dds_create_publisher");
}

inline dds_entity_t create_subscriber(dds_entity_t participant, std::string_view partition) {
  const std::string name(partition);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_partition1(qos, name.c_str());
  const dds_entity_t subscriber = dds_create_subscriber(participant, qos, nullptr);
  dds_delete_qos(qos);
  return check(subscriber, "dds_create_subscriber");
}

// A key-only sample for instance operations; points into the strings, owns nothing.
inline ncbridge_bus_Envelope key_sample(const std::string& key, const std::string& subkey) {
  ncbridge_bus_Envelope s{};
  s.id = const_cast<char*>(key.c_str());
  s.sub_id = const_cast<char*>(subkey.c_str());
  return s;
}

}  // namespace ncbridge::bus::detail
