#include "growthuq/stats/sample_summary.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "growthuq/core/error.hpp"

namespace growthuq {

double sorted_quantile(std::span<const double> sorted, double p) {
  const double h = static_cast<double>(sorted.size() - 1) * p;
  const double floor_h = std::floor(h);
  const auto below = static_cast<std::size_t>(floor_h);
  if (below + 1 >= sorted.size()) return sorted.back();
  return sorted[below] + (h - floor_h) * (sorted[below + 1] - sorted[below]);
}

SampleSummary summarize(std::span<const double> values) {
  if (values.empty()) throw InputError("sample summary", "no values to summarize");
  std::vector<double> sorted(values.begin(), values.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (!std::isfinite(sorted[i])) {
      throw InputError("sample summary", "value " + std::to_string(i + 1) + " is not finite");
    }
  }
  std::sort(sorted.begin(), sorted.end());
  return summarize_sorted(sorted);
}

SampleSummary summarize_sorted(std::span<const double> sorted) {
  if (sorted.empty()) throw InputError("sample summary", "no values to summarize");
  SampleSummary summary;
  summary.count = sorted.size();
  summary.p10 = sorted_quantile(sorted, 0.10);
  summary.q1 = sorted_quantile(sorted, 0.25);
  summary.median = sorted_quantile(sorted, 0.50);
  summary.q3 = sorted_quantile(sorted, 0.75);
  summary.p90 = sorted_quantile(sorted, 0.90);
  return summary;
}

}  // namespace growthuq
