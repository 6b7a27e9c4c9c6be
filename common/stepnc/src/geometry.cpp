#include "ncbridge/stepnc/geometry.hpp"

#include <cmath>

namespace ncbridge::stepnc {

double sweep_degrees(const TrimmedCircle& arc) {
  double sweep = arc.sense_agreement ? arc.trim_2_parameter - arc.trim_1_parameter
                                     : arc.trim_1_parameter - arc.trim_2_parameter;
  sweep = std::fmod(sweep, 360.0);
  if (sweep <= 0) sweep += 360.0;
  return sweep;
}

}  // namespace ncbridge::stepnc
