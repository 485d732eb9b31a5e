#include "growthuq/distributions/lognormal.hpp"

#include <gsl/gsl_cdf.h>

#include <cmath>
#include <numbers>

#include "distributions/checks.hpp"
#include "distributions/vector_exp.hpp"
#include "growthuq/distributions/normal.hpp"
#include "growthuq/distributions/standard_normal.hpp"

namespace growthuq {
namespace {

// z = Phi^-1(0.75) to 20 digits (mpmath: mp.dps = 30; print(-sqrt(2) * erfinv(-0.5))).
constexpr double upper_quartile_z = 0.67448975019608174320;

}  // namespace

Lognormal::Lognormal(double mu, double sigma) : mu_(mu), sigma_(sigma) {
  detail::gsl_errors_return();
  detail::require_finite("lognormal", "mu", mu);
  detail::require_positive("lognormal", "sigma", sigma);
}

Lognormal Lognormal::from_median_iqr(double median, double iqr) {
  detail::require_positive("lognormal", "median", median);
  detail::require_positive("lognormal", "iqr", iqr);
  return Lognormal(std::log(median), std::asinh(iqr / (2.0 * median)) / upper_quartile_z);
}

double Lognormal::median() const { return std::exp(mu_); }

double Lognormal::iqr() const { return 2.0 * median() * std::sinh(upper_quartile_z * sigma_); }

double pdf(const Lognormal& distribution, double x) {
  if (!(x > 0.0)) return 0.0;
  if (std::isinf(x)) return 0.0;
  const double z = (std::log(x) - distribution.mu()) / distribution.sigma();
  return std::exp(-0.5 * z * z) / (x * distribution.sigma() * std::sqrt(2.0 * std::numbers::pi));
}

double cdf(const Lognormal& distribution, double x) {
  if (std::isnan(x)) return x;
  if (x <= 0.0) return 0.0;
  return gsl_cdf_ugaussian_P((std::log(x) - distribution.mu()) / distribution.sigma());
}

double quantile(const Lognormal& distribution, double u) {
  detail::require_probability("lognormal", u);
  if (u == 0.0) return 0.0;
  // The same exp as the batch form (vector_exp.hpp), so both agree bit for bit.
  return detail::exp_affine(standard_normal_quantile(u), distribution.mu(), distribution.sigma());
}

}  // namespace growthuq
