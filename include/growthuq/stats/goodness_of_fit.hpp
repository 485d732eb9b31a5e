// Goodness of fit of a sample to a fully specified continuous law, from the law's cdf at the
// sorted sample: the Kolmogorov-Smirnov distance D and the Anderson-Darling A^2 (which
// weights the tails more). Used by `growthuq fit` to compare distribution families.
#pragma once

#include <span>

namespace growthuq {

// D = max_i max(i/n - F(x_(i)), F(x_(i)) - (i-1)/n), i = 1..n (Kolmogorov 1933).
// `sorted_cdf` holds F(x_(i)) for the sample sorted ascending: non-decreasing values in
// [0, 1], at least one (std::invalid_argument otherwise; these are computed, not read).
double kolmogorov_smirnov_statistic(std::span<const double> sorted_cdf);

// A^2 = -n - (1/n) sum_i (2i - 1) [ln F(x_(i)) + ln(1 - F(x_(n+1-i)))]
// (Anderson & Darling 1954; Stephens 1974, eq. 4). +inf when some F is exactly 0 or 1 (a
// point the law deems impossible). Same requirements on `sorted_cdf` as above.
double anderson_darling_statistic(std::span<const double> sorted_cdf);

}  // namespace growthuq
