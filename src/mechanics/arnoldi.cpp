// phi(x) = x K1(x)/K0(x) and its inverse (Arnoldi et al. 2000). Three regimes, each exact to
// double precision where it is used:
//   x < 1e-5        ascending series of K0, K1 (Abramowitz & Stegun 9.6.13, 9.6.11):
//                   phi = [1 - (x^2/2)(L + 1/2)] / [L + (x^2/4)(L + 1)], L = ln(2/x) - gamma;
//                   the neglected terms are O(x^4 L) relative, below 1e-19.
//   1e-5 <= x < 1e3 GSL's exponentially scaled K0, K1 (the e^x factors cancel in the ratio,
//                   so nothing underflows past x ~ 700).
//   x >= 1e3        Hankel expansions of K0, K1 (A&S 9.7.2) divided as power series in 1/x:
//                   phi = x + 1/2 - 1/(8x) + 1/(8x^2) - 25/(128x^3) + 13/(32x^4)
//                   - 1073/(1024x^5) + O(x^-6); the first omitted term is 3e-21 of phi at
//                   x = 1e3 (checked against mpmath). Smoother than the ratio of two GSL
//                   values, which wobbles by a few ulp at large x.
#include "growthuq/mechanics/arnoldi.hpp"

#include <cfloat>
#include <cmath>
#include <limits>
#include <numbers>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_bessel.h>

#include "core/gsl_errors.hpp"

namespace growthuq {
namespace {

constexpr double series_limit = 1e-5;
constexpr double asymptotic_limit = 1e3;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

double phi_series(double x) {
  // ln 2 - ln x rather than ln(2/x): 2/x overflows for subnormal x.
  const double L = std::numbers::ln2 - std::log(x) - std::numbers::egamma;
  const double x2 = x * x;
  return (1.0 - 0.5 * x2 * (L + 0.5)) / (L + 0.25 * x2 * (L + 1.0));
}

double phi_scaled_bessel(double x) {
  detail::gsl_errors_return();
  gsl_sf_result k0;
  gsl_sf_result k1;
  if (gsl_sf_bessel_K0_scaled_e(x, &k0) != GSL_SUCCESS) return nan;
  if (gsl_sf_bessel_K1_scaled_e(x, &k1) != GSL_SUCCESS) return nan;
  return x * (k1.val / k0.val);
}

// phi - x for x >= 1e3, without the cancellation of subtracting x from phi.
double phi_minus_x_asymptotic(double x) {
  const double u = 1.0 / x;
  return 0.5 + u * (-0.125 + u * (0.125 + u * (-25.0 / 128 + u * (13.0 / 32 + u * (-1073.0 / 1024)))));
}

// Inverse of the x < 1e-20 regime, where the series is phi = 1/L to double precision:
// x = 2 exp(-gamma - 1/phi). Underflows gracefully to a subnormal or 0.
constexpr double closed_form_small_x = 1e-20;

}  // namespace

double arnoldi_phi(double x) {
  if (!(x >= 0.0)) return nan;
  if (x == 0.0) return 0.0;
  if (x < series_limit) return phi_series(x);
  if (x < asymptotic_limit) return phi_scaled_bessel(x);
  return x + phi_minus_x_asymptotic(x);  // +inf stays +inf
}

double arnoldi_phi_derivative(double x) {
  if (!(x > 0.0)) return nan;
  const double phi = arnoldi_phi(x);
  // (phi - x)(phi + x)/x avoids the cancellation of phi^2 - x^2 for large x.
  const double phi_minus_x = x < asymptotic_limit ? phi - x : phi_minus_x_asymptotic(x);
  return phi_minus_x * ((phi + x) / x);
}

double arnoldi_phi_inverse(double phi) {
  if (!(phi >= 0.0)) return nan;
  if (phi == 0.0 || phi == std::numeric_limits<double>::infinity()) return phi;

  static const double phi_small = arnoldi_phi(closed_form_small_x);
  if (phi < phi_small) return 2.0 * std::exp(-std::numbers::egamma - 1.0 / phi);
  // Inverse of phi = x + 1/2 - 1/(8x) + O(x^-2): relative error O(x^-3), below 1e-24 here.
  if (phi > 1e8) return phi - 0.5 + 0.125 / (phi - 0.5);

  // Bracket in t = ln x. x < phi(x) (K1 > K0) gives phi(phi) > phi; phi(x) < x + 1/2
  // (Segura 2011: K1/K0 < (1/2 + sqrt(1/4 + x^2))/x < 1 + 1/(2x)) gives phi(phi - 1/2) < phi.
  // For phi <= 1 the small-x form phi ~ 1/L puts the root near 2 exp(-gamma - 1/phi); the
  // lower end starts below that and walks down until it brackets.
  struct Target {
    double phi;
  } target{phi};
  gsl_function f;
  f.function = [](double t, void* params) {
    return arnoldi_phi(std::exp(t)) - static_cast<Target*>(params)->phi;
  };
  f.params = &target;

  const double t_hi = std::log(phi);
  double t_lo = phi > 1.0 ? std::log(phi - 0.5)
                          : std::log(2.0) - std::numbers::egamma - 1.0 / phi - 1.0;
  while (f.function(t_lo, f.params) > 0.0) t_lo -= 4.0;
  const double f_hi = f.function(t_hi, f.params);
  if (f_hi == 0.0) return phi;
  if (f.function(t_lo, f.params) == 0.0) return std::exp(t_lo);

  detail::gsl_errors_return();
  gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  if (solver == nullptr) return nan;
  double t = nan;
  if (gsl_root_fsolver_set(solver, &f, t_lo, t_hi) == GSL_SUCCESS) {
    for (int iteration = 0; iteration < 200; ++iteration) {
      if (gsl_root_fsolver_iterate(solver) != GSL_SUCCESS) break;
      t = gsl_root_fsolver_root(solver);
      const double lo = gsl_root_fsolver_x_lower(solver);
      const double hi = gsl_root_fsolver_x_upper(solver);
      // A tolerance in t is a relative tolerance in x: a few ulp of t (absolute near t = 0).
      if (gsl_root_test_interval(lo, hi, 4.0 * DBL_EPSILON, 4.0 * DBL_EPSILON) != GSL_CONTINUE) break;
    }
  }
  gsl_root_fsolver_free(solver);
  if (std::isnan(t)) return nan;
  // One Newton step in x polishes what t cannot resolve (an ulp of t = ln x is up to ~20 ulp
  // of x for large x): phi'(x) = (phi - x)(phi + x)/x.
  const double x = std::exp(t);
  const double slope = arnoldi_phi_derivative(x);
  return slope > 0.0 ? x - (arnoldi_phi(x) - phi) / slope : x;
}

}  // namespace growthuq
