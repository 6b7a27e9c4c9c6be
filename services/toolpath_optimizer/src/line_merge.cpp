// Collinear merging: can one line replace the moves from vertex `first` to `last`?
#include <algorithm>

#include "ncbridge/toolpath_optimizer/fit.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"

namespace ncbridge::toolpath_optimizer {

// Each vertex is paired with the point of the line at its projection, held back so the pairing
// runs forward only; the line is within the band when every pair is (fit.hpp).
bool line_fits(std::span<const FitVertex> v, std::size_t first, std::size_t last, double tolerance) {
  const Vec3 a = v[first].p;
  const Vec3 d = v[last].p - a;
  const double length2 = dot(d, d);
  if (length2 <= 1e-24) return false;
  const double tolerance2 = tolerance * tolerance;
  double t_max = 0;
  for (std::size_t i = first + 1; i < last; ++i) {
    const Vec3 q = v[i].p - a;
    const double t = std::clamp(std::max(t_max, dot(q, d) / length2), 0.0, 1.0);
    t_max = t;
    const Vec3 off = q - t * d;
    if (dot(off, off) > tolerance2) return false;
  }
  return true;
}

}  // namespace ncbridge::toolpath_optimizer
