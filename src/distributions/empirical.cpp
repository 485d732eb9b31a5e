#include "growthuq/distributions/empirical.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "distributions/checks.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq {

Empirical::Empirical(std::vector<double> data) : sorted_(std::move(data)) {
  for (std::size_t i = 0; i < sorted_.size(); ++i) {
    detail::require_finite("empirical", "values[" + std::to_string(i + 1) + "]", sorted_[i]);
  }
  std::sort(sorted_.begin(), sorted_.end());
  if (sorted_.size() < 2 || sorted_.front() == sorted_.back()) {
    throw InputError("empirical", "values: expected at least two distinct numbers, got " +
                                      std::to_string(sorted_.size()) + " value(s)" +
                                      (sorted_.size() >= 2 ? ", all equal" : ""));
  }
}

// Index i with x(i) <= x < x(i+1) for lower <= x < upper (0-based, right-continuous at ties).
namespace {

std::size_t interval_of(const std::vector<double>& sorted, double x) {
  return static_cast<std::size_t>(std::upper_bound(sorted.begin(), sorted.end(), x) - sorted.begin()) - 1;
}

}  // namespace

double pdf(const Empirical& distribution, double x) {
  const auto& s = distribution.sorted_data();
  if (!(x >= s.front() && x < s.back())) return 0.0;
  const std::size_t i = interval_of(s, x);
  return 1.0 / (static_cast<double>(s.size() - 1) * (s[i + 1] - s[i]));
}

double cdf(const Empirical& distribution, double x) {
  const auto& s = distribution.sorted_data();
  if (std::isnan(x)) return x;
  if (x < s.front()) return 0.0;
  if (x >= s.back()) return 1.0;
  const std::size_t i = interval_of(s, x);
  const double within = (x - s[i]) / (s[i + 1] - s[i]);
  return (static_cast<double>(i) + within) / static_cast<double>(s.size() - 1);
}

double quantile(const Empirical& distribution, double u) {
  detail::require_probability("empirical", u);
  const auto& s = distribution.sorted_data();
  if (u == 1.0) return s.back();
  const double position = u * static_cast<double>(s.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(position), s.size() - 2);
  const double within = position - static_cast<double>(i);
  return within == 0.0 ? s[i] : s[i] + within * (s[i + 1] - s[i]);
}

}  // namespace growthuq
