#include "growthuq/distributions/normal.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>

#include <cmath>

#include "distributions/checks.hpp"
#include "growthuq/distributions/standard_normal.hpp"

namespace growthuq {

Normal::Normal(double mean, double sd) : mean_(mean), sd_(sd) {
  detail::gsl_errors_return();
  detail::require_finite("normal", "mean", mean);
  detail::require_positive("normal", "sd", sd);
}

double pdf(const Normal& distribution, double x) {
  return gsl_ran_gaussian_pdf(x - distribution.mean(), distribution.sd());
}

double cdf(const Normal& distribution, double x) {
  if (std::isnan(x)) return x;
  return gsl_cdf_ugaussian_P((x - distribution.mean()) / distribution.sd());
}

double quantile(const Normal& distribution, double u) {
  detail::require_probability("normal", u);
  return distribution.mean() + distribution.sd() * standard_normal_quantile(u);
}

}  // namespace growthuq
