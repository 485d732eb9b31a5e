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

enum class FitFamily { lognormal, normal, gamma, weibull, beta };

// The families compared by default for a positive quantity (k, h, d, d0, tau, v_exp).
inline constexpr FitFamily all_fit_families[] = {FitFamily::lognormal, FitFamily::normal, FitFamily::gamma,
                                                 FitFamily::weibull};
// ... and for a fraction (einf): the beta law first, bounded like the fraction itself; the
// others compete only while every value they can draw stays in [0, 1] (raw_line_fit.hpp).
inline constexpr FitFamily fraction_fit_families[] = {FitFamily::beta, FitFamily::lognormal, FitFamily::normal,
                                                      FitFamily::gamma, FitFamily::weibull};

std::string_view to_string(FitFamily family);
std::optional<FitFamily> parse_fit_family(std::string_view name);
// The family whose ML fit gives laws like `distribution` (lognormal, normal, gamma, weibull,
// beta); nullopt for truncated_normal, uniform and empirical, which have no fit here.
std::optional<FitFamily> fit_family_of(const Distribution& distribution);

// Lognormal, gamma, Weibull and beta need every value > 0 (beta also below its upper end).
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
//              increases in k; scale = (mean x^k)^{1/k} (Cohen 1965);
//   beta       of y = x / fraction_upper (fraction_upper: where the fraction is 1 in the data's
//              unit, 100 for %, fixed, not estimated): alpha and beta solve
//              psi(alpha) - psi(alpha + beta) = mean ln y, psi(beta) - psi(alpha + beta) =
//              mean ln(1 - y), by Newton's method from the method-of-moments estimate (the
//              log-likelihood is concave in (alpha, beta)) (Eq. (D5)).
// InputError (location "fit <family>") for fewer than two values, all values equal, a
// non-finite value or a non-positive value for a positive family, a value at or above
// fraction_upper for beta; callers that know file rows validate first so users see row numbers.
FitResult fit_distribution(FitFamily family, std::span<const double> data, double fraction_upper = 1.0);

}  // namespace growthuq
