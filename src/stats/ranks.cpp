#include "growthuq/stats/ranks.hpp"

#include <algorithm>
#include <bit>
#include <memory>
#include <numeric>
#include <vector>

#include "stats/keyed_sort.hpp"

namespace growthuq {

namespace {

constexpr std::size_t radix_threshold = 1024;  // below this std::stable_sort is as fast

// Stable argsort in linear time: records (key32 << 32 | index) sorted by detail::sort_records,
// then runs of equal 32-bit keys (values within a relative 2^-20 of each other) put in the
// order of the doubles.
std::vector<std::uint32_t> radix_argsort(std::span<const double> values) {
  const std::size_t n = values.size();
  // Uninitialized: every element is written before it is read.
  std::unique_ptr<std::uint64_t[]> records(new std::uint64_t[n]), scratch(new std::uint64_t[n]);
  for (std::size_t i = 0; i < n; ++i) records[i] = detail::keyed_record(detail::order_key32(values[i]), static_cast<std::uint32_t>(i));
  const std::span<std::uint64_t> sorted(records.get(), n);
  detail::sort_records(sorted, std::span<std::uint64_t>(scratch.get(), n), 32);
  detail::order_equal_keys(sorted, [&](std::uint32_t i) { return values[i]; });
  std::vector<std::uint32_t> order(n);
  for (std::size_t p = 0; p < n; ++p) order[p] = detail::record_index(records[p]);
  return order;
}

}  // namespace

std::vector<std::uint32_t> argsort(std::span<const double> values) {
  if (values.size() >= radix_threshold) return radix_argsort(values);
  std::vector<std::uint32_t> order(values.size());
  std::iota(order.begin(), order.end(), std::uint32_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return values[a] < values[b];
  });
  return order;
}

std::vector<std::uint32_t> ordinal_ranks(std::span<const double> values) {
  const std::vector<std::uint32_t> order = argsort(values);
  std::vector<std::uint32_t> rank(values.size());
  for (std::size_t position = 0; position < order.size(); ++position) {
    rank[order[position]] = static_cast<std::uint32_t>(position);
  }
  return rank;
}

std::vector<double> average_ranks(std::span<const double> values) {
  const std::vector<std::uint32_t> order = argsort(values);
  std::vector<double> rank(values.size());
  std::size_t first = 0;
  while (first < order.size()) {
    std::size_t last = first + 1;
    while (last < order.size() && values[order[last]] == values[order[first]]) ++last;
    // positions first..last-1 (0-based) tie: each gets the mean 1-based position
    const double mean = 0.5 * static_cast<double>(first + last + 1);
    for (std::size_t p = first; p < last; ++p) rank[order[p]] = mean;
    first = last;
  }
  return rank;
}

}  // namespace growthuq
