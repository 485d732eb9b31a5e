#include "growthuq/stats/goodness_of_fit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace growthuq {
namespace {

void check_sorted_cdf(std::span<const double> sorted_cdf, const char* who) {
  if (sorted_cdf.empty()) throw std::invalid_argument(std::string(who) + ": empty sample");
  for (std::size_t i = 0; i < sorted_cdf.size(); ++i) {
    const double f = sorted_cdf[i];
    if (!(f >= 0.0 && f <= 1.0) || (i > 0 && f < sorted_cdf[i - 1])) {
      throw std::invalid_argument(std::string(who) + ": cdf values must be non-decreasing in [0, 1]");
    }
  }
}

}  // namespace

double kolmogorov_smirnov_statistic(std::span<const double> sorted_cdf) {
  check_sorted_cdf(sorted_cdf, "kolmogorov_smirnov_statistic");
  const double n = static_cast<double>(sorted_cdf.size());
  double d = 0.0;
  for (std::size_t i = 0; i < sorted_cdf.size(); ++i) {
    const double rank = static_cast<double>(i);
    d = std::max({d, (rank + 1.0) / n - sorted_cdf[i], sorted_cdf[i] - rank / n});
  }
  return d;
}

double anderson_darling_statistic(std::span<const double> sorted_cdf) {
  check_sorted_cdf(sorted_cdf, "anderson_darling_statistic");
  const std::size_t n = sorted_cdf.size();
  if (sorted_cdf.front() == 0.0 || sorted_cdf.back() == 1.0) return HUGE_VAL;
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    // log1p(-F) keeps ln(1 - F) accurate where F is small.
    sum += static_cast<double>(2 * i + 1) * (std::log(sorted_cdf[i]) + std::log1p(-sorted_cdf[n - 1 - i]));
  }
  const double size = static_cast<double>(n);
  return -size - sum / size;
}

}  // namespace growthuq
