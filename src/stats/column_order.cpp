#include "stats/column_order.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "core/large_buffer.hpp"
#include "stats/keyed_sort.hpp"

namespace growthuq {

namespace {

// How many elements ahead the scatter of ranks prefetches.
constexpr std::size_t prefetch_distance = 32;

}  // namespace

ColumnOrder order_column(std::span<const double> values, std::span<const std::size_t> positions) {
  const std::size_t n = values.size();
  if (n > 0x7fffffffULL) throw std::invalid_argument("order_column: more than 2^31 - 1 values");
  for (const std::size_t position : positions) {
    if (position >= n) throw std::out_of_range("order_column: order statistic beyond the column");
  }
  // The wanted positions in ascending order, each with where its value goes.
  std::vector<std::pair<std::size_t, std::size_t>> wanted;
  for (std::size_t k = 0; k < positions.size(); ++k) wanted.emplace_back(positions[k], k);
  std::sort(wanted.begin(), wanted.end());
  std::size_t next_wanted = 0;

  ColumnOrder order;
  order.order_statistics.resize(positions.size());
  order.twice_ranks.resize(n);
  if (n == 0) return order;
  std::uint64_t lowest = ~std::uint64_t{0}, highest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isnan(values[i])) throw std::invalid_argument("order_column: NaN at position " + std::to_string(i));
    const std::uint64_t key = detail::order_key64(values[i]);
    lowest = std::min(lowest, key);
    highest = std::max(highest, key);
  }
  const detail::RangeKey key(lowest, highest);
  detail::LargeBuffer<std::uint64_t> records(n), scratch(n);
  for (std::size_t i = 0; i < n; ++i) records[i] = detail::keyed_record(key(values[i]), static_cast<std::uint32_t>(i));
  const auto value_of = [&](std::uint32_t i) { return values[i]; };
  // 24 sorted key bits; the insertion pass of sort_bucket orders what shares them.
  std::uint32_t* rank = order.twice_ranks.data();
  detail::for_each_sorted_run(std::span<std::uint64_t>(records.data(), n), std::span<std::uint64_t>(scratch.data(), n), 24,
                              [&](std::size_t first, std::span<std::uint64_t> sorted) {
                                detail::order_equal_keys(sorted, value_of);
                                const std::size_t size = sorted.size();
                                // Groups of equal values (equal keys first, then equal doubles;
                                // equal values never straddle two runs, their keys being equal).
                                std::size_t begin = 0;
                                while (begin < size) {
                                  std::size_t end = begin + 1;
                                  while (end < size && detail::record_key(sorted[end]) == detail::record_key(sorted[begin]) &&
                                         values[detail::record_index(sorted[end])] ==
                                             values[detail::record_index(sorted[begin])]) {
                                    ++end;
                                  }
                                  // Positions first + begin .. first + end - 1 (0-based) share the
                                  // mean 1-based rank (2 first + begin + end + 1)/2.
                                  const auto twice = static_cast<std::uint32_t>(2 * first + begin + end + 1);
                                  for (std::size_t p = begin; p < end; ++p) {
                                    if (p + prefetch_distance < size) {
                                      __builtin_prefetch(rank + detail::record_index(sorted[p + prefetch_distance]), 1);
                                    }
                                    rank[detail::record_index(sorted[p])] = twice;
                                  }
                                  begin = end;
                                }
                                while (next_wanted < wanted.size() && wanted[next_wanted].first < first + size) {
                                  const std::uint32_t i = detail::record_index(sorted[wanted[next_wanted].first - first]);
                                  order.order_statistics[wanted[next_wanted].second] = values[i];
                                  ++next_wanted;
                                }
                              });
  return order;
}

}  // namespace growthuq
