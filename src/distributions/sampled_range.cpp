#include "growthuq/distributions/sampled_range.hpp"

#include <cmath>
#include <utility>
#include <variant>

#include "growthuq/core/numbers.hpp"

namespace growthuq {

std::optional<std::string> sampled_range_problem(const Distribution& law, double to_si) {
  // Families whose support is x > 0: a 0 there is an underflow, not a value of the law.
  const bool positive = std::holds_alternative<Lognormal>(law) || std::holds_alternative<Gamma>(law) ||
                        std::holds_alternative<Weibull>(law);
  // A quantile is monotone, so its two ends bound every value in between. The upper end first:
  // an inf is the worse of the two problems when a law has both.
  for (const auto& [u, name] : {std::pair{highest_drawn_probability, "1 - 2^-53 (1 - 1.1e-16)"},
                                std::pair{lowest_drawn_probability, "2^-86 (1.3e-26)"}}) {
    const double value = quantile(law, u);
    const double si = value * to_si;
    const bool bad = !std::isfinite(value) || !std::isfinite(si) || (positive && !(value > 0.0 && si > 0.0));
    if (!bad) continue;
    std::string text = "its quantile at probability " + std::string(name) + " is " + format_double(value);
    if (std::isfinite(value) && value != 0.0 && to_si != 1.0) text += " (" + format_double(si) + " in SI units)";
    return text;
  }
  return std::nullopt;
}

std::optional<std::string> fraction_range_problem(const Distribution& law, double upper) {
  // Both ends of the drawn range bound every value a design draws (the quantile is monotone).
  const double highest = quantile(law, highest_drawn_probability);
  if (!(highest <= upper)) {
    return "its quantile at probability 1 - 2^-53 (1 - 1.1e-16) is " + format_double(highest) + ", above " +
           format_double(upper) + " (a fraction of 1)";
  }
  const double lowest = quantile(law, lowest_drawn_probability);
  if (!(lowest >= 0.0)) return "its quantile at probability 2^-86 (1.3e-26) is " + format_double(lowest) + ", below 0";
  return std::nullopt;
}

}  // namespace growthuq
