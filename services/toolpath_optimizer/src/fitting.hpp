#pragma once
// What the fitter's files share (not part of the library's interface).
#include <span>
#include <vector>

#include "ncbridge/toolpath_optimizer/fit.hpp"

namespace ncbridge::toolpath_optimizer {

// The filament per length of every move from `first` to `last` is within `variance` of their
// mean (or none of them extrudes).
bool extrusion_rate_fits(std::span<const FitVertex> v, std::size_t first, std::size_t last, double variance);


}  // namespace ncbridge::toolpath_optimizer
