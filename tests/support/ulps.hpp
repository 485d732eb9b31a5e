// Distances between doubles in units in the last place, for accuracy tests whose tolerance is
// a few ulps of a reference value.
#pragma once

#include <cmath>

namespace growthuq::testing {

// |a - b| in ulps of the reference `b` (the spacing of doubles just above |b|); 0 when equal.
inline double ulps_apart(double a, double b) {
  if (a == b) return 0.0;
  const double ulp = std::nextafter(std::fabs(b), HUGE_VAL) - std::fabs(b);
  return std::fabs(a - b) / ulp;
}

}  // namespace growthuq::testing
