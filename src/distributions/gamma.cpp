// Gamma quantile: GSL's inverse (gsl_cdf_gamma_Pinv / _Qinv) in the body, polished by a few
// Newton steps (polish()). In the far lower tail (u < 1e-10), and wherever GSL's iteration
// gives up and returns NaN (small shapes at u ~ 1e-9, large shapes at u ~ 1e-10): Newton's
// method on ln P(k, x) = ln u in t = ln x, with ln P from the series
// P(k, x) = x^k e^-x / Gamma(k + 1) sum_n x^n / ((k+1)...(k+n)) (Abramowitz & Stegun 6.5.29)
// so that it never underflows. The start x0 = (u Gamma(k + 1))^(1/k) is a lower bound of the
// quantile (P(k, x) <= x^k / Gamma(k + 1)), and ln P is increasing and concave in t (its slope
// x f / P = 1 / int_0^1 v^(k-1) e^(x (1 - v)) dv decreases in x), so the iterates rise
// monotonically to the root without overshooting.
#include "growthuq/distributions/gamma.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_sf_gamma.h>

#include <algorithm>
#include <cmath>

#include "distributions/checks.hpp"

namespace growthuq {
namespace {

// ln P(k, x) for x > 0, finite however small P is: GSL's P while it is a normal double (it
// is more accurate for large shapes than the series, whose k ln x - ln Gamma(k + 1) cancels),
// the series below.
double log_lower_regularized_gamma(double k, double x) {
  const double p = gsl_sf_gamma_inc_P(k, x);
  if (p > 1e-280) return std::log(p);
  double term = 1.0, sum = 1.0;
  for (int n = 1; n < 100000 && term > 1e-17 * sum; ++n) {
    term *= x / (k + n);
    sum += term;
  }
  return k * std::log(x) - x - gsl_sf_lngamma(k + 1.0) + std::log(sum);
}

// Quantile of the unit-scale gamma law at lower-tail probability u in (0, 1/2].
double lower_tail_quantile(double u, double k) {
  const double log_u = std::log(u);
  const double log_gamma_k = gsl_sf_lngamma(k);
  double t = (log_u + gsl_sf_lngamma(k + 1.0)) / k;
  // Below x ~ 1e-100 the series' next term (relative x / (k + 1)) is far below eps, so the
  // start is the answer; exp(t) underflows to 0 when the quantile is below the smallest
  // subnormal double (e.g. shape 0.5, u = 1e-300: x ~ 1e-600).
  if (t < -230.0) return std::exp(t);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double x = std::exp(t);
    const double log_p = log_lower_regularized_gamma(k, x);
    // d ln P / d t = x f(x) / P with ln(x f(x)) = k t - x - ln Gamma(k).
    const double slope = std::exp(k * t - x - log_gamma_k - log_p);
    const double step = (log_p - log_u) / slope;
    t -= step;
    if (!(std::fabs(step) > 2e-16 * std::max(1.0, std::fabs(t)))) break;
  }
  return std::exp(t);
}

// A few Newton steps in t = ln x on ln P(k, x) = ln u (lower) or ln Q(k, x) = ln(1 - u)
// (upper) from GSL's estimate: GSL's inverse can stop early for large shapes (shape 1e5 at
// 1 - u = 1e-12 was off by 7e-4 relative), and the polish costs two incomplete gammas.
double polish(double x, double k, double log_target, bool upper) {
  if (!(x > 0.0) || !std::isfinite(x)) return x;
  const double log_gamma_k = gsl_sf_lngamma(k);
  double t = std::log(x);
  for (int iteration = 0; iteration < 6; ++iteration) {
    const double xi = std::exp(t);
    const double log_tail = upper ? std::log(gsl_sf_gamma_inc_Q(k, xi)) : log_lower_regularized_gamma(k, xi);
    const double slope = std::exp(k * t - xi - log_gamma_k - log_tail) * (upper ? -1.0 : 1.0);
    const double step = (log_tail - log_target) / slope;
    if (!std::isfinite(step)) break;
    t -= step;
    if (!(std::fabs(step) > 2e-16 * std::max(1.0, std::fabs(t)))) break;
  }
  return std::exp(t);
}

}  // namespace

Gamma::Gamma(double shape, double scale) : shape_(shape), scale_(scale) {
  detail::gsl_errors_return();
  detail::require_positive("gamma", "shape", shape);
  detail::require_positive("gamma", "scale", scale);
}

double pdf(const Gamma& distribution, double x) {
  if (!(x >= 0.0) || std::isinf(x)) return 0.0;
  return gsl_ran_gamma_pdf(x, distribution.shape(), distribution.scale());
}

double cdf(const Gamma& distribution, double x) {
  if (std::isnan(x)) return x;
  if (x <= 0.0) return 0.0;
  if (std::isinf(x)) return 1.0;
  return gsl_cdf_gamma_P(x, distribution.shape(), distribution.scale());
}

double quantile(const Gamma& distribution, double u) {
  detail::require_probability("gamma", u);
  if (u == 0.0) return 0.0;
  if (u == 1.0) return HUGE_VAL;
  const double k = distribution.shape();
  if (u <= 0.5) {
    const double x = u < 1e-10 ? HUGE_VAL : gsl_cdf_gamma_Pinv(u, k, 1.0);
    return distribution.scale() * (std::isfinite(x) ? polish(x, k, std::log(u), false) : lower_tail_quantile(u, k));
  }
  // The upper-tail inverse on 1 - u (exact for u >= 1/2) keeps the upper tail's digits.
  const double complement = 1.0 - u;
  return distribution.scale() * polish(gsl_cdf_gamma_Qinv(complement, k, 1.0), k, std::log(complement), true);
}

}  // namespace growthuq
