#pragma once
// Mach3/Mach4 read through the Fanuc front-end: the RS274 subset Mach implements, with Mach's
// conventions (services/interpreter/dialects/mach3.yaml).
#include "fanuc/fanuc_front_end.hpp"

namespace ncbridge::interpreter::mach3 {

fanuc::Flavour mach3_flavour();

}  // namespace ncbridge::interpreter::mach3
