#pragma once
// A DDS call failed (no network interface, bad configuration, resource limit): not the user's
// input, so not an InputError. The message names the call and Cyclone's return code.
#include <stdexcept>
#include <string>

namespace ncbridge::bus {

class BusError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ncbridge::bus
