#include "growthuq/stats/multifidelity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gsl/gsl_cdf.h>

namespace growthuq {

namespace {

double mean_of(std::span<const double> values) {
  double sum = 0;
  for (const double value : values) sum += value;
  return sum / static_cast<double>(values.size());
}

// Sample covariance (divisor n - 1) of two equally long series.
double covariance(std::span<const double> x, std::span<const double> y) {
  const double mx = mean_of(x), my = mean_of(y);
  double sum = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sum += (x[i] - mx) * (y[i] - my);
  return sum / static_cast<double>(x.size() - 1);
}

IntervalEstimate interval(double estimate, double standard_error, double t) {
  return {estimate, standard_error, estimate - t * standard_error, estimate + t * standard_error};
}

// The difference estimate of the distribution function of h (Eq. (T9)) as weighted jumps:
// +1/M at every surrogate value of the M samples, +1/N at every paired h, -1/N at every paired
// surrogate value; jumps at one position are merged and those that cancel dropped.
class DifferenceCdf {
 public:
  DifferenceCdf(std::span<const double> high, std::span<const double> surrogate_all, std::size_t pairs) {
    const double m = static_cast<double>(surrogate_all.size()), n = static_cast<double>(pairs);
    std::vector<std::pair<double, double>> jumps;
    for (const double value : surrogate_all) jumps.emplace_back(value, 1.0 / m);
    for (std::size_t i = 0; i < pairs; ++i) {
      jumps.emplace_back(high[i], 1.0 / n);
      jumps.emplace_back(surrogate_all[i], -1.0 / n);
    }
    std::sort(jumps.begin(), jumps.end());
    double cumulative = 0;
    for (std::size_t j = 0; j < jumps.size();) {
      double weight = 0;
      const double position = jumps[j].first;
      for (; j < jumps.size() && jumps[j].first == position; ++j) weight += jumps[j].second;
      if (std::abs(weight) < 1e-12 / m) continue;
      cumulative += weight;
      // Each jump counts at its middle (Hazen's plotting position, Hyndman and Fan 1996 type 5):
      // for a plain sample this is the usual median, the mean of the middle two of an even count,
      // where the step function's first crossing would be the lower one, biased by half a step.
      nodes_.emplace_back(position, cumulative - weight / 2);
    }
  }

  // The q-quantile of the monotone rearrangement of the piecewise linear F through the nodes
  // (Chernozhukov, Fernandez-Val and Galichon 2010): the first node plus the length over which
  // F < q. F is not monotone (the -1/N jumps), and its first crossing of q would come early
  // where F wiggles about q, biased low by a good part of 1/N of the distribution; the
  // rearrangement is monotone and no farther from the true distribution function in any L^p
  // norm (their Proposition 1). For a monotone F it is the plain inverse.
  double inverse(double q) const {
    double position = nodes_.front().first;
    if (nodes_.front().second >= q) return position;
    for (std::size_t j = 1; j < nodes_.size(); ++j) {
      const auto& [t0, f0] = nodes_[j - 1];
      const auto& [t1, f1] = nodes_[j];
      if (f0 < q && f1 < q) {
        position += t1 - t0;
      } else if (f0 < q || f1 < q) {  // the segment crosses q at t0 + (q - f0) / (f1 - f0) (t1 - t0)
        const double crossing = (q - f0) / (f1 - f0);
        position += (f0 < q ? crossing : 1.0 - crossing) * (t1 - t0);
      }
    }
    return position;
  }

 private:
  std::vector<std::pair<double, double>> nodes_;  // (position, F at the middle of its jump)
};

void require(bool condition, const char* what) {
  if (!condition) throw std::invalid_argument(std::string("estimate_multifidelity: ") + what);
}

}  // namespace

MultifidelityEstimate estimate_multifidelity(std::span<const double> high, std::span<const double> low,
                                             std::span<const double> low_all, double quantile_level, double level) {
  const std::size_t n = high.size(), m = low_all.size();
  require(low.size() == n, "high and low differ in length");
  require(n >= 3, "fewer than 3 pairs");
  require(m >= n, "fewer low-fidelity samples than pairs");
  require(level > 0 && level < 1 && quantile_level > 0 && quantile_level < 1, "level outside (0, 1)");
  for (std::size_t i = 0; i < m; ++i) require(std::isfinite(low_all[i]), "a non-finite low-fidelity value");
  for (std::size_t i = 0; i < n; ++i) require(std::isfinite(high[i]) && low[i] == low_all[i], "a non-finite or unpaired pair");

  MultifidelityEstimate result;
  result.pairs = n;
  result.low_samples = m;
  result.quantile_level = quantile_level;
  const double nn = static_cast<double>(n), mm = static_cast<double>(m);

  // (T7) The bias of the low fidelity: the mean paired difference.
  std::vector<double> difference(n);
  for (std::size_t i = 0; i < n; ++i) difference[i] = high[i] - low[i];
  const double sd_difference = std::sqrt(covariance(difference, difference));
  result.bias = interval(mean_of(difference), sd_difference / std::sqrt(nn), gsl_cdf_tdist_Pinv(0.5 + level / 2, nn - 1));

  // (T8) The control variate: surrogate s = a + alpha l, alpha = cov(h, l) / var(l), a such that
  // s and h agree in mean over the pairs; the estimate is mean_M(s) + mean_N(h - s).
  const double var_low = covariance(low, low), var_high = covariance(high, high), cov = covariance(high, low);
  result.alpha = var_low > 0 ? cov / var_low : 0.0;
  result.correlation = var_low > 0 && var_high > 0 ? cov / std::sqrt(var_low * var_high) : 0.0;
  const double offset = mean_of(high) - result.alpha * mean_of(low);
  std::vector<double> surrogate_all(m);
  for (std::size_t j = 0; j < m; ++j) surrogate_all[j] = offset + result.alpha * low_all[j];
  const std::span<const double> surrogate(surrogate_all.data(), n);
  std::vector<double> residual(n);
  for (std::size_t i = 0; i < n; ++i) residual[i] = high[i] - surrogate[i];
  const double t_regression = gsl_cdf_tdist_Pinv(0.5 + level / 2, nn - 2);
  // Var = var(s) / M + var(e) / N; the residuals of the fitted line are uncorrelated with s, and
  // their variance divides by N - 2 (two fitted coefficients).
  double residual_squares = 0;
  for (const double e : residual) residual_squares += e * e;
  const double var_surrogate_all = m >= 2 ? covariance(surrogate_all, surrogate_all) : 0.0;
  const double se_mean = std::sqrt(var_surrogate_all / mm + residual_squares / (nn - 2) / nn);
  result.mean = interval(mean_of(surrogate_all) + mean_of(residual), se_mean, t_regression);
  result.high_only_standard_error = std::sqrt(var_high / nn);

  // (T9) The quantile: the difference estimate of the distribution function with the same
  // surrogate, F(t) = mean_M 1{s <= t} + mean_N (1{h <= t} - 1{s <= t}), inverted at the level;
  // Woodruff's interval inverts F at level -+ t se(F(estimate)).
  const DifferenceCdf cdf(high, surrogate_all, n);
  const double q = cdf.inverse(quantile_level);
  std::vector<double> below_all(m), difference_below(n);
  for (std::size_t j = 0; j < m; ++j) below_all[j] = surrogate_all[j] <= q ? 1.0 : 0.0;
  for (std::size_t i = 0; i < n; ++i) difference_below[i] = (high[i] <= q ? 1.0 : 0.0) - below_all[i];
  const std::span<const double> below_paired(below_all.data(), n);
  // The N pairs are among the M samples: Var = (var(I) + 2 cov(I, D)) / M + var(D) / N.
  const double var_cdf = std::max(0.0, ((m >= 2 ? covariance(below_all, below_all) : 0.0) +
                                        2 * covariance(below_paired, difference_below)) / mm +
                                           covariance(difference_below, difference_below) / nn);
  const double se_cdf = std::sqrt(var_cdf);
  result.quantile.estimate = q;
  result.quantile.low = cdf.inverse(quantile_level - t_regression * se_cdf);
  result.quantile.high = cdf.inverse(quantile_level + t_regression * se_cdf);
  // The standard error of the quantile from the interval's width (Woodruff 1952, Eq. 5).
  result.quantile.standard_error = (result.quantile.high - result.quantile.low) / (2 * t_regression);
  return result;
}

}  // namespace growthuq
