// Per-line, per-quantity summaries of a campaign (the rows of summary.csv and results.h5):
// quantiles, mean and standard deviation, and a distribution-free 95 % confidence interval of
// the median from order statistics (Conover 1999, "Practical Nonparametric Statistics", 3.2).
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/evaluation/line_result.hpp"
#include "growthuq/evaluation/sample_status.hpp"

namespace growthuq {

// Order-statistic ranks (1-based) of a confidence interval of the median: with B ~ binomial(n,
// 1/2) the number of samples below the true median of a continuous law,
// P(X(lower) <= median <= X(upper)) = P(lower <= B <= upper - 1) = 1 - 2 P(B <= lower - 1) for
// the symmetric choice upper = n + 1 - lower. `lower` is the largest rank whose coverage is still
// >= level. When even the full range [X(1), X(n)] (coverage 1 - 2^(1-n)) falls short, i.e. n <= 5
// for 95 %, `reached` is false and lower = 1, upper = n (n = 0 gives 0, 0).
struct MedianConfidenceRanks {
  std::size_t lower = 0;
  std::size_t upper = 0;
  double coverage = 0;  // exact coverage of [X(lower), X(upper)] for continuous laws
  bool reached = false;
};

// level in (0, 1); std::invalid_argument otherwise (a programming error, not user input).
MedianConfidenceRanks median_confidence_ranks(std::size_t n, double level = 0.95);

// Whether a sample enters the statistics of a column: when the column holds a value for it
// (src/stats/README.md, Eq. (T3)). An input holds every drawn value; an output holds a value
// exactly where its model computed one, since a model leaves NaN wherever it flags a sample or
// finds it flagged (evaluate_checked enforces it), except under its valued statuses (v = 0
// for no_growth). So a sample flagged by a later model (its growth rate failed) still counts
// for p and E, which were computed, and what the statistics count is what samples.csv shows
// as a non-empty cell.
inline bool holds_value(double value) noexcept { return std::isfinite(value); }

// The summary of one column over the samples that hold a value (above); n_flagged counts the
// others, the samples the quantity lacks (0 for an input). Quantiles use numpy's "linear" rule
// (sorted_quantile); sd divides by n - 1.
// Cells that are undefined are NaN and writers print them as empty cells:
//   n = 0: every statistic;  n = 1: sd;  n <= 5: median_ci_low/high (95 % not reachable, see
//   MedianConfidenceRanks; reporting the range as a "95 %" interval would overstate it).
QuantitySummary summarize_quantity(const std::string& line, const ResultColumn& column);

// InputError at `location` naming the summary's line, quantity and statistic when a statistic
// it defines (every one but those the rules above leave undefined for its n) is not finite:
// counted values so large (above ~1e154 for sd) that double precision cannot hold their sum or
// squares. Such a summary is refused rather than written with an inf or an empty cell that
// reads as "undefined".
void require_finite_statistics(const QuantitySummary& summary, std::string_view location);

// The same in two halves, for a caller that has the counted values' order from elsewhere (one
// sort serving the ranks too): the 0-based positions of the ascending order it reads (sorted,
// unique), and the summary from the values at those positions plus the counted values' mean
// and squared deviations, summed in the samples' order (sample_moments) as summarize_quantity
// does, so both give the same bits. n_flagged = column.values.size() - moments.count.
struct SampleMoments {
  std::size_t count = 0;
  double mean = 0;
  double squared_deviations = 0;  // sum of (x - mean)^2
};
SampleMoments sample_moments(std::span<const double> values);
std::vector<std::size_t> summary_positions(std::size_t n);
QuantitySummary summary_from_order(const std::string& line, const ResultColumn& column, std::size_t n_flagged,
                                   const SampleMoments& moments, std::span<const double> order_statistics);

}  // namespace growthuq
