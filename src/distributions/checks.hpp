// Shared validation of the distribution component: parameter checks that name the family and
// parameter, the probability check of every quantile, and the one place GSL's
// abort-on-error handler is switched off.
#pragma once

#include <string_view>

namespace growthuq::detail {

// Switches GSL's default error handler (print and abort) off, once per process, so a GSL
// domain or convergence error returns a status/NaN that the caller handles instead of killing
// the run. Called by every distribution constructor and fitter before any GSL call; cheap
// after the first call (a function-local static).
void gsl_errors_return();

// InputError "<family>: <key> = '<value>': expected a finite number" unless value is finite.
void require_finite(std::string_view family, std::string_view key, double value);
// As require_finite, and value > 0.
void require_positive(std::string_view family, std::string_view key, double value);

// InputError "<family> quantile: u = '<u>': expected a probability in [0, 1]".
[[noreturn]] void throw_bad_probability(std::string_view family, double u);

inline void require_probability(std::string_view family, double u) {
  if (!(u >= 0.0 && u <= 1.0)) throw_bad_probability(family, u);
}

}  // namespace growthuq::detail
