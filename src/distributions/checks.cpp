#include "distributions/checks.hpp"

#include <cmath>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"

namespace growthuq::detail {

void require_finite(std::string_view family, std::string_view key, double value) {
  if (!std::isfinite(value)) throw_bad_value(family, key, format_double(value), "a finite number");
}

void require_positive(std::string_view family, std::string_view key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw_bad_value(family, key, format_double(value), "a positive finite number");
  }
}

void throw_bad_probability(std::string_view family, double u) {
  throw_bad_value(std::string(family) + " quantile", "u", format_double(u), "a probability in [0, 1]");
}

}  // namespace growthuq::detail
