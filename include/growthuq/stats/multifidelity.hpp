// Multifidelity estimates of a high-fidelity model's mean and quantiles from N paired runs of a
// high- and a low-fidelity model and M >= N runs of the low fidelity alone, the N pairs being
// the first N of the M samples (src/stats/README.md, Eqs. (T7)-(T9)): the low fidelity's bias
// (mean of h - l), the control-variate estimate of the mean of h (Peherstorfer, Willcox and
// Gunzburger 2016) and the difference estimate of a quantile of h (Rao, Kovar and Mantel 1990,
// Woodruff's interval), each with its interval.
#pragma once

#include <cstddef>
#include <span>

namespace growthuq {

// An estimate with its standard error and a two-sided interval at the requested level.
struct IntervalEstimate {
  double estimate = 0;
  double standard_error = 0;
  double low = 0;
  double high = 0;
};

struct MultifidelityEstimate {
  std::size_t pairs = 0;        // N: samples run by both models
  std::size_t low_samples = 0;  // M: samples run by the low fidelity
  double correlation = 0;       // rho of h and l over the pairs
  double alpha = 0;             // the control-variate coefficient cov(h, l) / var(l) over the pairs
  IntervalEstimate bias;        // mean of h - l (Student t, N - 1 degrees of freedom)
  IntervalEstimate mean;        // of h (Eq. (T8); Student t, N - 2 degrees of freedom)
  double high_only_standard_error = 0;  // s_h / sqrt(N): the mean's from the pairs alone
  double quantile_level = 0.5;
  IntervalEstimate quantile;    // of h at quantile_level (Eq. (T9); Woodruff's interval)
};

// `high` and `low` hold the N paired values (same order), `low_all` the M values of the low
// fidelity whose first N are `low` (checked). std::invalid_argument (a programming error: the
// caller keeps the finite pairs) for N < 3, M < N, a non-finite value, level or quantile level
// outside (0, 1). A low fidelity constant over the pairs gives alpha = 0 (no control).
MultifidelityEstimate estimate_multifidelity(std::span<const double> high, std::span<const double> low,
                                             std::span<const double> low_all, double quantile_level = 0.5,
                                             double level = 0.95);

}  // namespace growthuq
