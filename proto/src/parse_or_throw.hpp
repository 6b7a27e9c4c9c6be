#pragma once
// Internal to ncbridge_proto: parse a Protobuf message from untrusted bytes or throw InputError.
#include <google/protobuf/message_lite.h>

#include <limits>
#include <string>
#include <string_view>

#include "ncbridge/common/error.hpp"

namespace ncbridge::wire::detail {

[[noreturn]] inline void malformed(const char* what, const std::string& why) {
  throw InputError({std::string("<") + what + ">", 0, 0}, why);
}

inline void parse_or_throw(google::protobuf::MessageLite& msg, std::string_view bytes, const char* what) {
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    malformed(what, "payload larger than 2 GiB");
  if (!msg.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())))
    malformed(what, std::string("not a ") + what + " (truncated or malformed Protobuf, " +
                        std::to_string(bytes.size()) + " bytes)");
}

template <class E>
E enum_in_range(int v, int count, const char* what, const char* field) {
  if (v < 0 || v >= count) malformed(what, std::string(field) + " out of range: " + std::to_string(v));
  return static_cast<E>(v);
}

}  // namespace ncbridge::wire::detail
