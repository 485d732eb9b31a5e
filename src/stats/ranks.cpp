#include "growthuq/stats/ranks.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

#include "stats/keyed_sort.hpp"

namespace growthuq {

namespace detail {

namespace {

// Insertion sort of whole records, linear when they are nearly sorted.
void insertion_sort(std::uint64_t* data, std::size_t n) {
  for (std::size_t p = 1; p < n; ++p) {
    const std::uint64_t record = data[p];
    if (data[p - 1] <= record) continue;
    std::size_t q = p;
    for (; q > 0 && data[q - 1] > record; --q) data[q] = data[q - 1];
    data[q] = record;
  }
}

// Stable LSD radix sort of data[0..n) on 8-bit digits at `shifts`, ping-ponging with `other`;
// the result ends in `data`. Used on one top-level bucket, which is small enough for L1/L2.
void local_radix_sort(std::uint64_t* data, std::uint64_t* other, std::size_t n, const int* shifts, int passes) {
  std::uint32_t count[4][256] = {};
  for (std::size_t i = 0; i < n; ++i) {
    for (int pass = 0; pass < passes; ++pass) ++count[pass][(data[i] >> shifts[pass]) & 255];
  }
  std::uint64_t* from = data;
  std::uint64_t* to = other;
  for (int pass = 0; pass < passes; ++pass) {
    if (count[pass][(from[0] >> shifts[pass]) & 255] == n) continue;
    std::uint32_t offset = 0;
    for (auto& c : count[pass]) offset += std::exchange(c, offset);
    for (std::size_t i = 0; i < n; ++i) to[count[pass][(from[i] >> shifts[pass]) & 255]++] = from[i];
    std::swap(from, to);
  }
  if (from != data) std::copy(from, from + n, data);
}

}  // namespace

void sort_records(std::span<std::uint64_t> records, std::span<std::uint64_t> scratch, int radix_bits) {
  // One most-significant-digit pass (8 bits, 256 buckets: the only pass that streams the whole
  // array through memory), then each bucket, now cache-resident, by least-significant-digit
  // passes of 8 bits on the key's next bits, then one insertion pass on whole records. Every
  // pass is stable, so records equal in the sorted bits stay in index order.
  constexpr int top_bits = 8;
  constexpr std::size_t top_buckets = std::size_t{1} << top_bits;
  constexpr std::size_t small_bucket = 48;  // insertion sort is faster below this
  const std::size_t n = records.size();
  if (n < 2) return;
  std::vector<std::uint32_t> start(top_buckets + 1, 0);
  for (const std::uint64_t record : records) ++start[(record >> (64 - top_bits)) + 1];
  for (std::size_t b = 0; b < top_buckets; ++b) start[b + 1] += start[b];
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (const std::uint64_t record : records) scratch[next[record >> (64 - top_bits)]++] = record;
  }
  const int local_passes = std::clamp((radix_bits - top_bits + 7) / 8, 0, 4);
  int shifts[4];
  for (int pass = 0; pass < local_passes; ++pass) shifts[pass] = 64 - top_bits - 8 * (local_passes - pass);
  for (std::size_t b = 0; b < top_buckets; ++b) {
    const std::size_t first = start[b];
    const std::size_t size = start[b + 1] - first;
    if (size == 0) continue;
    if (size > small_bucket) local_radix_sort(scratch.data() + first, records.data() + first, size, shifts, local_passes);
    std::copy_n(scratch.data() + first, size, records.data() + first);
  }
  insertion_sort(records.data(), n);
}

}  // namespace detail

namespace {

// Unsigned key whose order is the order of the doubles (sign bit flipped for positives, all
// bits flipped for negatives); +0.0 and -0.0 map to the same key so they tie. Its top 32 bits
// (sign, exponent, 20 mantissa bits) are a monotone 32-bit key.
std::uint32_t order_key32(double value) {
  const auto bits = std::bit_cast<std::uint64_t>(value + 0.0);
  return static_cast<std::uint32_t>(((bits >> 63) != 0 ? ~bits : bits | (std::uint64_t{1} << 63)) >> 32);
}

constexpr std::size_t radix_threshold = 1024;  // below this std::stable_sort is as fast

// Stable argsort in linear time: records (key32 << 32 | index) sorted by detail::sort_records,
// then runs of equal 32-bit keys (values within a relative 2^-20 of each other) put in the
// order of the doubles.
std::vector<std::uint32_t> radix_argsort(std::span<const double> values) {
  const std::size_t n = values.size();
  // Uninitialized: every element is written before it is read.
  std::unique_ptr<std::uint64_t[]> records(new std::uint64_t[n]), scratch(new std::uint64_t[n]);
  for (std::size_t i = 0; i < n; ++i) records[i] = detail::keyed_record(order_key32(values[i]), static_cast<std::uint32_t>(i));
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
