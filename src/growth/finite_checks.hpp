// NaN-safe range tests shared by the growth evaluators (a NaN fails every comparison, so each
// test is false for NaN without a separate isnan).
#pragma once

#include <cmath>
#include <initializer_list>
#include <limits>

namespace growthuq::growth_detail {

inline bool positive_finite(double x) noexcept {
  return x > 0.0 && x <= std::numeric_limits<double>::max();
}

inline bool non_negative_finite(double x) noexcept {
  return x >= 0.0 && x <= std::numeric_limits<double>::max();
}

// Positive, finite and not subnormal: a result that kept full double precision.
inline bool positive_normal(double x) noexcept {
  return x >= std::numeric_limits<double>::min() && x <= std::numeric_limits<double>::max();
}

// Within [2^-100, 2^100]: a product or quotient of up to five such numbers stays far inside
// the normal double range, so it can be computed directly with full precision.
inline bool moderate(double x) noexcept { return x >= 0x1p-100 && x <= 0x1p100; }

// The product of `factors` divided by the product of `divisors` (all positive and finite),
// without intermediate overflow or underflow: mantissas (frexp, in [0.5, 1)) are multiplied
// and divided while the binary exponents are summed, and ldexp applies the sum once. Same
// number of roundings as the direct expression; the slow path for inputs that are not all
// moderate(), where the result is out of range only if the true value is.
inline double scaled_ratio(std::initializer_list<double> factors,
                           std::initializer_list<double> divisors) noexcept {
  double mantissa = 1.0;
  int exponent = 0;
  for (double x : factors) {
    int e = 0;
    mantissa *= std::frexp(x, &e);
    exponent += e;
  }
  for (double x : divisors) {
    int e = 0;
    mantissa /= std::frexp(x, &e);
    exponent -= e;
  }
  return std::ldexp(mantissa, exponent);
}

}  // namespace growthuq::growth_detail
