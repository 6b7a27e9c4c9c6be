#pragma once
// One DDS sample of any topic (proto/envelope.idl) as a C++ value.
#include <cstdint>
#include <string>

namespace ncbridge::bus {

struct Envelope {
  std::string key;       // see topics.hpp for what key and subkey mean on each topic
  std::string subkey;
  std::uint64_t seq = 0;
  std::uint32_t kind = 0;
  bool last = false;
  std::string payload;   // serialized Protobuf bytes (ncbridge/wire/*.hpp, canonical/proto_codec.hpp)
  friend bool operator==(const Envelope&, const Envelope&) = default;
};

// What a reader hands back: a sample, or news about an instance (key, subkey) with no data.
enum class InstanceState : std::uint8_t {
  Alive,      // the instance has a live writer
  Disposed,   // its writer disposed it (a worker leaving cleanly, a job withdrawn)
  NoWriters,  // every writer of it is gone: unregistered, or dead (liveliness lost)
};

struct Received {
  Envelope envelope;       // key and subkey always set; the rest only when has_data
  bool has_data = true;
  InstanceState state = InstanceState::Alive;
};

}  // namespace ncbridge::bus
