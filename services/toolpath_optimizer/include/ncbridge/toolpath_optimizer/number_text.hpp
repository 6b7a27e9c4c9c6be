#pragma once
// Numbers as G-code and KRL write them: fixed decimals, trailing zeros dropped, no "-0".
#include <string>

namespace ncbridge::toolpath_optimizer {

// Appends `value` with at most `decimals` decimals to `out`.
void append_number(std::string& out, double value, int decimals);

}  // namespace ncbridge::toolpath_optimizer
