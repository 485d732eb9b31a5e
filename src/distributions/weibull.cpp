#include "growthuq/distributions/weibull.hpp"

#include <cmath>

#include "distributions/checks.hpp"

namespace growthuq {

Weibull::Weibull(double shape, double scale) : shape_(shape), scale_(scale) {
  detail::require_positive("weibull", "shape", shape);
  detail::require_positive("weibull", "scale", scale);
}

double pdf(const Weibull& distribution, double x) {
  if (!(x >= 0.0) || std::isinf(x)) return 0.0;
  const double k = distribution.shape();
  const double t = x / distribution.scale();
  if (t == 0.0) return k < 1.0 ? HUGE_VAL : (k == 1.0 ? 1.0 / distribution.scale() : 0.0);
  const double tk = std::pow(t, k);
  return k / distribution.scale() * tk / t * std::exp(-tk);
}

double cdf(const Weibull& distribution, double x) {
  if (std::isnan(x)) return x;
  if (x <= 0.0) return 0.0;
  // -expm1 keeps the lower tail's relative accuracy where 1 - exp(-t^k) would cancel.
  return -std::expm1(-std::pow(x / distribution.scale(), distribution.shape()));
}

double quantile(const Weibull& distribution, double u) {
  detail::require_probability("weibull", u);
  // x = lambda (-ln(1 - u))^{1/k}: log1p(-u) is exact-relative for small u, and for u >= 1/2
  // the difference 1 - u is exact, so both tails keep their digits.
  const double minus_log_survival = u <= 0.5 ? -std::log1p(-u) : -std::log(1.0 - u);
  return distribution.scale() * std::pow(minus_log_survival, 1.0 / distribution.shape());
}

}  // namespace growthuq
