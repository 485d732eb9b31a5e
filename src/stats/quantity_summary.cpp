#include "growthuq/stats/quantity_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gsl/gsl_cdf.h>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"

namespace growthuq {

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

// P(B <= k) for B ~ binomial(n, 1/2). GSL evaluates it through the regularized incomplete beta
// function, so the cost does not grow with n.
double binomial_half_cdf(std::size_t k, std::size_t n) {
  return gsl_cdf_binomial_P(static_cast<unsigned int>(k), 0.5, static_cast<unsigned int>(n));
}

constexpr double summary_levels[] = {0.10, 0.25, 0.50, 0.75, 0.90};

}  // namespace

MedianConfidenceRanks median_confidence_ranks(std::size_t n, double level) {
  if (!(level > 0 && level < 1)) throw std::invalid_argument("median_confidence_ranks: level must be in (0, 1)");
  if (n > std::numeric_limits<unsigned int>::max()) {
    throw std::invalid_argument("median_confidence_ranks: n exceeds the range of GSL's binomial CDF");
  }
  MedianConfidenceRanks ranks;
  if (n == 0) return ranks;
  // Coverage of [X(l), X(n+1-l)] is 1 - 2 F(l - 1), decreasing in l. Binary search for the
  // largest l in [1, ceil(n/2)] with 2 F(l - 1) <= 1 - level; l = 1 has F(0) = 2^-n.
  const double tail = 0.5 * (1.0 - level);
  std::size_t good = 0;  // largest l known to satisfy the bound (0: none)
  std::size_t low = 1, high = (n + 1) / 2;
  while (low <= high) {
    const std::size_t mid = low + (high - low) / 2;
    if (binomial_half_cdf(mid - 1, n) <= tail) {
      good = mid;
      low = mid + 1;
    } else {
      high = mid - 1;
    }
  }
  ranks.reached = good > 0;
  ranks.lower = ranks.reached ? good : 1;
  ranks.upper = n + 1 - ranks.lower;
  ranks.coverage = 1.0 - 2.0 * binomial_half_cdf(ranks.lower - 1, n);
  return ranks;
}

std::vector<std::size_t> summary_positions(std::size_t n) {
  std::vector<std::size_t> positions;
  if (n == 0) return positions;
  const MedianConfidenceRanks ranks = median_confidence_ranks(n, 0.95);
  positions = {ranks.lower - 1, ranks.upper - 1};
  for (const double level : summary_levels) {
    const auto below = static_cast<std::size_t>(std::floor(static_cast<double>(n - 1) * level));
    positions.push_back(below);
    if (below + 1 < n) positions.push_back(below + 1);
  }
  std::sort(positions.begin(), positions.end());
  positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
  return positions;
}

SampleMoments sample_moments(std::span<const double> values) {
  // Two passes (mean, then squared deviations) avoid the cancellation of the one-pass formula;
  // both in the order given (the samples' order), so every caller gets the same bits.
  SampleMoments moments;
  moments.count = values.size();
  if (values.empty()) return moments;
  double total = 0;
  for (const double value : values) total += value;
  moments.mean = total / static_cast<double>(values.size());
  for (const double value : values) moments.squared_deviations += (value - moments.mean) * (value - moments.mean);
  return moments;
}

QuantitySummary summary_from_order(const std::string& line, const ResultColumn& column, std::size_t n_flagged,
                                   const SampleMoments& moments, std::span<const double> order_statistics) {
  QuantitySummary summary;
  summary.line = line;
  summary.quantity = column.quantity;
  summary.unit = column.unit != nullptr ? std::string(column.unit->symbol) : std::string();
  const std::size_t n = moments.count;
  summary.n = n;
  summary.n_flagged = n_flagged;
  if (n == 0) {
    summary.median = summary.q1 = summary.q3 = summary.iqr = summary.p10 = summary.p90 = not_a_number;
    summary.mean = summary.sd = summary.median_ci_low = summary.median_ci_high = not_a_number;
    return summary;
  }
  const std::vector<std::size_t> positions = summary_positions(n);
  if (order_statistics.size() != positions.size()) {
    throw std::invalid_argument("summary_from_order: expected the order statistics of summary_positions");
  }
  const auto at = [&](std::size_t position) {
    return order_statistics[static_cast<std::size_t>(std::lower_bound(positions.begin(), positions.end(), position) -
                                                     positions.begin())];
  };
  // sorted_quantile's rule (numpy's "linear"), reading only x[floor h] and x[floor h + 1].
  const auto quantile = [&](double level) {
    const double h = static_cast<double>(n - 1) * level;
    const double floor_h = std::floor(h);
    const auto below = static_cast<std::size_t>(floor_h);
    if (below + 1 >= n) return at(below);
    return at(below) + (h - floor_h) * (at(below + 1) - at(below));
  };
  summary.median = quantile(0.50);
  summary.q1 = quantile(0.25);
  summary.q3 = quantile(0.75);
  summary.iqr = summary.q3 - summary.q1;
  summary.p10 = quantile(0.10);
  summary.p90 = quantile(0.90);
  summary.mean = moments.mean;
  summary.sd = n > 1 ? std::sqrt(moments.squared_deviations / static_cast<double>(n - 1)) : not_a_number;
  const MedianConfidenceRanks ranks = median_confidence_ranks(n, 0.95);
  if (ranks.reached) {
    summary.median_ci_low = at(ranks.lower - 1);
    summary.median_ci_high = at(ranks.upper - 1);
  } else {
    summary.median_ci_low = summary.median_ci_high = not_a_number;
  }
  return summary;
}

void require_finite_statistics(const QuantitySummary& summary, std::string_view location) {
  if (summary.n == 0) return;
  const bool interval = median_confidence_ranks(summary.n, 0.95).reached;
  const std::pair<const char*, double> defined[] = {
      {"median", summary.median}, {"q1", summary.q1},   {"q3", summary.q3},     {"iqr", summary.iqr},
      {"p10", summary.p10},       {"p90", summary.p90}, {"mean", summary.mean}, {"sd", summary.n > 1 ? summary.sd : 0.0},
      {"median_ci_low", interval ? summary.median_ci_low : 0.0},
      {"median_ci_high", interval ? summary.median_ci_high : 0.0}};
  for (const auto& [name, value] : defined) {
    if (std::isfinite(value)) continue;
    const std::string unit = summary.unit.empty() || summary.unit == "1" ? "" : " " + summary.unit;
    throw InputError(std::string(location),
                     "line '" + summary.line + "', " + summary.quantity + ": " + name + " = " + format_double(value) +
                         ": expected a finite statistic of " + std::to_string(summary.n) +
                         " values; they are too large for double precision (median " + format_double(summary.median) +
                         unit + ", p90 " + format_double(summary.p90) + unit + "): check the line's laws or data");
  }
}

QuantitySummary summarize_quantity(const std::string& line, const ResultColumn& column) {
  std::vector<double> values;
  values.reserve(column.values.size());
  for (const double value : column.values) {
    if (holds_value(value)) values.push_back(value);
  }
  const SampleMoments moments = sample_moments(values);
  // Only a few order statistics are needed: select them (std::nth_element, linear time) in
  // ascending order, each within what is left above the previous one, instead of sorting all n
  // (a sort of 1e6 doubles costs ~4x as much).
  const std::vector<std::size_t> positions = summary_positions(values.size());
  std::vector<double> order_statistics;
  std::size_t start = 0;
  for (const std::size_t position : positions) {
    std::nth_element(values.begin() + static_cast<std::ptrdiff_t>(start),
                     values.begin() + static_cast<std::ptrdiff_t>(position), values.end());
    order_statistics.push_back(values[position]);
    start = position + 1;
  }
  return summary_from_order(line, column, column.values.size() - values.size(), moments, order_statistics);
}

}  // namespace growthuq
