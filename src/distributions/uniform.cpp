#include "growthuq/distributions/uniform.hpp"

#include <cmath>

#include "distributions/checks.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"

namespace growthuq {

Uniform::Uniform(double lower, double upper) : lower_(lower), upper_(upper) {
  detail::require_finite("uniform", "lower", lower);
  detail::require_finite("uniform", "upper", upper);
  if (!(upper > lower)) {
    throw_bad_value("uniform", "upper", format_double(upper), "a number above lower = " + format_double(lower));
  }
}

double pdf(const Uniform& distribution, double x) {
  if (x < distribution.lower() || x > distribution.upper()) return 0.0;
  return 1.0 / (distribution.upper() - distribution.lower());
}

double cdf(const Uniform& distribution, double x) {
  if (std::isnan(x)) return x;
  if (x <= distribution.lower()) return 0.0;
  if (x >= distribution.upper()) return 1.0;
  return (x - distribution.lower()) / (distribution.upper() - distribution.lower());
}

double quantile(const Uniform& distribution, double u) {
  detail::require_probability("uniform", u);
  // Interpolating from the nearer end keeps x exact at both ends.
  const double width = distribution.upper() - distribution.lower();
  return u <= 0.5 ? distribution.lower() + u * width : distribution.upper() - (1.0 - u) * width;
}

}  // namespace growthuq
