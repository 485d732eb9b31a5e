// The values a design can draw from a law. A Latin hypercube point lies strictly inside its
// stratum, at least 2^-54 of the stratum's width from its lower edge (random_stream.hpp's
// bits_to_open_unit) and never above the largest double below 1 (latin_hypercube.cpp's
// stratum_points), and a design has at most 2^32 - 1 strata: every probability a design draws
// is in [lowest_drawn_probability, highest_drawn_probability], whatever the sample count. A law
// whose quantile at either end is not a finite number (lognormal mu = 800, Weibull shape 1e-3, a
// normal sd of 1e308), or is 0 for a law of positive values (gamma shape 0.05), would put inf or
// 0 into designs and results: such a law is refused where it is read or fitted, before any
// sample.
#pragma once

#include <optional>
#include <string>

#include "growthuq/distributions/distribution.hpp"

namespace growthuq {

inline constexpr double lowest_drawn_probability = 0x1.0p-86;         // 1.3e-26
inline constexpr double highest_drawn_probability = 1.0 - 0x1.0p-53;  // 1 - 1.1e-16

// What sampled_range_problem requires, for messages ("...: expected <this>").
inline constexpr const char* sampled_range_expectation =
    "a law whose values are finite, and above 0 for a law of positive values, at every probability a design draws "
    "(2^-86 to 1 - 2^-53)";

// Why `law` cannot be sampled, or nullopt when it can: its quantiles at both ends of the drawn
// range, multiplied by `to_si` (1 for the law's own unit, a unit's factor for its values in SI),
// are finite, and positive for the families of positive values (lognormal, gamma, Weibull).
// The text names the end and the value, e.g.
//   "its quantile at probability 1 - 1.1e-16 is inf".
std::optional<std::string> sampled_range_problem(const Distribution& law, double to_si = 1.0);

// For a law of a fraction (e_inf) whose value 1 is `upper` in the law's unit (1 in frac, 100 in
// %): why a design could draw a value outside [0, upper], or nullopt. A fraction above 1
// (E_inf > E_r(0)) or below 0 is no tube's; such samples would be flagged and dropped, and the
// rest would pass for the line's. The text names the end and the value, e.g.
//   "its quantile at probability 1 - 1.1e-16 is 187, above 100 (a fraction of 1)".
std::optional<std::string> fraction_range_problem(const Distribution& law, double upper);

}  // namespace growthuq
