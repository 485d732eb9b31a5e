// The standard normal quantile Phi^-1(u), used by every normal-based law and for the van der
// Waerden scores of Iman-Conover (Eq. (C2), src/correlation/README.md). Accurate at both
// tails: for u in (0, 1) the result is finite (|x| <= 38.5 for u >= DBL_TRUE_MIN's
// neighbourhood), u = 0 and u = 1 give -inf and +inf; u outside [0, 1] or NaN is an InputError.
#pragma once

#include <span>

namespace growthuq {

double standard_normal_quantile(double u);

// x[i] = Phi^-1(u[i]); the spans must have equal sizes (std::invalid_argument otherwise). Same values as
// the scalar form, bit for bit.
void standard_normal_quantiles(std::span<const double> u, std::span<double> x);

}  // namespace growthuq
