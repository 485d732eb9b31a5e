// Shared validation of the distribution component: parameter checks that name the family and
// parameter and the probability check of every quantile (GSL's abort handler is switched off
// through core/gsl_errors.hpp).
#pragma once

#include "core/gsl_errors.hpp"

#include <string_view>

namespace growthuq::detail {

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
