// What the per-line statistics need from one column's order, from a single sort: the average
// ranks (Spearman's correlation is the Pearson correlation of those) and chosen order statistics
// (quantiles, the order statistics that bound the median's confidence interval).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "growthuq/core/large_vector.hpp"

namespace growthuq {

struct ColumnOrder {
  // twice_ranks[i] = 2 x the average rank of values[i]: 1-based ranks, ties sharing the mean of
  // their positions ("fractional ranking", as average_ranks in ranks.hpp), doubled so that they
  // are whole numbers (n < 2^31).
  LargeVector<std::uint32_t> twice_ranks;
  // order_statistics[k] = the value at 0-based position positions[k] of the ascending order.
  std::vector<double> order_statistics;
};

// `values` must hold no NaN (std::invalid_argument otherwise); `positions` must be below
// values.size() (std::out_of_range otherwise); at most 2^31 - 1 values (std::invalid_argument). A
// radix sort on order-preserving keys, with runs of equal keys put in the exact order of the
// values.
ColumnOrder order_column(std::span<const double> values, std::span<const std::size_t> positions);

}  // namespace growthuq
