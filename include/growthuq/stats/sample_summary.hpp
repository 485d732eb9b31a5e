// Sample quantiles and the summaries the engine reports for every variable and result
// (median, interquartile range, 10-90 % range).
#pragma once

#include <cstddef>
#include <span>

namespace growthuq {

// Quantile p in [0,1] of ascending `sorted` values by linear interpolation between order
// statistics: h = (n - 1) p, x[floor h] + (h - floor h)(x[floor h + 1] - x[floor h]).
// This is Hyndman & Fan (1996) type 7, numpy's default "linear" method and R's default.
double sorted_quantile(std::span<const double> sorted, double p);

struct SampleSummary {
  std::size_t count = 0;
  double p10 = 0, q1 = 0, median = 0, q3 = 0, p90 = 0;
  double iqr() const { return q3 - q1; }
};

// Summary of finite `values` (any order). InputError (location "sample summary") for an empty
// sample or a non-finite value.
SampleSummary summarize(std::span<const double> values);

// The same of values already in ascending order (not checked).
SampleSummary summarize_sorted(std::span<const double> sorted);

}  // namespace growthuq
