// Maximum-likelihood fits of the parametric families to raw per-tube measurements, with the
// numbers a user needs to choose among them (Eqs. (D5)-(D8), src/distributions/README.md):
// log-likelihood, AIC and the Kolmogorov-Smirnov and Anderson-Darling statistics of the fitted law.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "growthuq/distributions/distribution.hpp"

namespace growthuq {

enum class FitFamily { lognormal, normal, gamma, weibull };

inline constexpr FitFamily all_fit_families[] = {FitFamily::lognormal, FitFamily::normal, FitFamily::gamma,
                                                 FitFamily::weibull};

std::string_view to_string(FitFamily family);
std::optional<FitFamily> parse_fit_family(std::string_view name);

// Lognormal, gamma and Weibull need every value > 0.
bool needs_positive_data(FitFamily family);

struct FitResult {
  FitFamily family;
  Distribution distribution;      // the ML estimate
  std::size_t sample_size = 0;
  int parameter_count = 2;
  double log_likelihood = 0;      // at the estimate, in closed form
  double aic = 0;                 // 2 parameter_count - 2 log_likelihood (Akaike 1974)
  double ks_statistic = 0;        // Kolmogorov-Smirnov D of the data against the estimate
  double ad_statistic = 0;        // Anderson-Darling A^2 (the estimate's parameters not corrected for)
};

// The ML fit of `family` to `data`:
//   normal     mean and sd (divisor n);
//   lognormal  the normal ML on ln x;
//   gamma      shape k from ln k - psi(k) = ln(mean) - mean(ln x), bracketed by
//              1/(2s) < k < 1/s because 1/(2k) < ln k - psi(k) < 1/k; scale = mean / k
//              (Choi & Wette 1969);
//   weibull    shape k from sum x^k ln x / sum x^k - 1/k = mean(ln x), whose left side
//              increases in k; scale = (mean x^k)^{1/k} (Cohen 1965).
// InputError (location "fit <family>") for fewer than two values, all values equal, a
// non-finite value or a non-positive value for a positive family; callers that know file
// rows validate first so users see row numbers.
FitResult fit_distribution(FitFamily family, std::span<const double> data);

}  // namespace growthuq
