// Wichura's algorithm AS241 (PPND16), Applied Statistics 37 (1988) 477-484: Phi^-1 to about
// 1e-16 relative accuracy by three rational approximations (central |p - 1/2| <= 0.425, then
// r = sqrt(-ln min(p, 1-p)) <= 5 and r > 5). It is the algorithm GSL's gsl_cdf_ugaussian_Pinv
// implements; this inlineable copy exists because the call into GSL dominated the batch
// quantile (~30 ns/value measured, vs ~6 ns inlined; see test_standard_normal.cpp, which
// checks it against GSL to a few ulps over a dense grid and both tails).
#pragma once

#include <cmath>
#include <cstddef>

namespace growthuq::detail {

// Horner evaluation of the ratio of two degree-7 polynomials, in the same order as GSL.
inline double rational7(const double (&a)[8], const double (&b)[8], double x) {
  double numerator = a[7];
  double denominator = b[7];
  for (int i = 6; i >= 0; --i) {
    numerator = x * numerator + a[i];
    denominator = x * denominator + b[i];
  }
  return numerator / denominator;
}

// Phi^-1(u) for u in [0, 1] (u = 0 and 1 give -inf and +inf). The tails use
// r = sqrt(-ln(min(u, 1 - u))), and 1 - u is exact for u >= 1/2, so the upper tail keeps the
// digits u carries. Coefficients from Wichura (1988), PPND16.
// Central region |u - 1/2| <= 0.425, as a function of q = u - 1/2 (branch-free, so batch
// loops vectorize it).
inline constexpr double central_a[8] = {3.3871328727963666080e0, 1.3314166789178437745e+2,
                                        1.9715909503065514427e+3, 1.3731693765509461125e+4,
                                        4.5921953931549871457e+4, 6.7265770927008700853e+4,
                                        3.3430575583588128105e+4, 2.5090809287301226727e+3};
inline constexpr double central_b[8] = {1.0, 4.2313330701600911252e+1,
                                        6.8718700749205790830e+2, 5.3941960214247511077e+3,
                                        2.1213794301586595867e+4, 3.9307895800092710610e+4,
                                        2.8729085735721942674e+4, 5.2264952788528545610e+3};

inline double as241_central(double q) { return q * rational7(central_a, central_b, 0.180625 - q * q); }

// The tails, |u - 1/2| > 0.425, as functions of r = sqrt(-ln(tail probability)): r <= 5, then
// r > 5.
inline constexpr double middle_c[8] = {1.42343711074968357734e0, 4.63033784615654529590e0,
                                       5.76949722146069140550e0, 3.64784832476320460504e0,
                                       1.27045825245236838258e0, 2.41780725177450611770e-1,
                                       2.27238449892691845833e-2, 7.74545014278341407640e-4};
inline constexpr double middle_d[8] = {1.0, 2.05319162663775882187e0,
                                       1.67638483018380384940e0, 6.89767334985100004550e-1,
                                       1.48103976427480074590e-1, 1.51986665636164571966e-2,
                                       5.47593808499534494600e-4, 1.05075007164441684324e-9};
inline constexpr double tail_e[8] = {6.65790464350110377720e0, 5.46378491116411436990e0,
                                     1.78482653991729133580e0, 2.96560571828504891230e-1,
                                     2.65321895265761230930e-2, 1.24266094738807843860e-3,
                                     2.71155556874348757815e-5, 2.01033439929228813265e-7};
inline constexpr double tail_f[8] = {1.0, 5.99832206555887937690e-1,
                                     1.36929880922735805310e-1, 1.48753612908506148525e-2,
                                     7.86869131145613259100e-4, 1.84631831751005468180e-5,
                                     1.42151175831644588870e-7, 2.04426310338993978564e-15};

// Tail values the batch quantile (standard_normal.cpp) evaluates together.
inline constexpr std::size_t as241_tail_batch = 256;

inline double as241(double u) {
  const double q = u - 0.5;
  if (std::fabs(q) <= 0.425) return as241_central(q);
  const double tail_probability = q < 0.0 ? u : 1.0 - u;
  if (tail_probability == 0.0) return q < 0.0 ? -HUGE_VAL : HUGE_VAL;
  const double r = std::sqrt(-std::log(tail_probability));
  const double magnitude = r <= 5.0 ? rational7(middle_c, middle_d, r - 1.6) : rational7(tail_e, tail_f, r - 5.0);
  return q < 0.0 ? -magnitude : magnitude;
}

}  // namespace growthuq::detail
