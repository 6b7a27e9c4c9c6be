#pragma once
// Internal: Cyclone return codes to BusError, and the QoS conversion (defined in qos_profiles.cpp).
#include <dds/dds.h>

#include <memory>
#include <string>

#include "ncbridge/bus/bus_error.hpp"
#include "ncbridge/bus/qos_profiles.hpp"

namespace ncbridge::bus::detail {

inline std::int32_t check(std::int32_t rc, const char* call) {
  if (rc < 0) throw BusError(std::string(call) + " failed: " + dds_strretcode(rc));
  return rc;
}

struct QosDeleter {
  void operator()(dds_qos_t* q) const { dds_delete_qos(q); }
};
using QosPtr = std::unique_ptr<dds_qos_t, QosDeleter>;

enum class Endpoint { Writer, Reader };
QosPtr make_qos(const QosProfile& profile, Endpoint endpoint);

}  // namespace ncbridge::bus::detail
