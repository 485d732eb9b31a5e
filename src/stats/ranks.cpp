#include "growthuq/stats/ranks.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <memory>
#include <numeric>
#include <utility>

namespace growthuq {

namespace {

// Unsigned key whose order is the order of the doubles (sign bit flipped for positives, all
// bits flipped for negatives); +0.0 and -0.0 map to the same key so they tie.
std::uint64_t order_key(double value) {
  const auto bits = std::bit_cast<std::uint64_t>(value + 0.0);
  return (bits >> 63) != 0 ? ~bits : bits | (std::uint64_t{1} << 63);
}

constexpr std::size_t radix_threshold = 1024;  // below this std::stable_sort is as fast
constexpr int digit_bits = 11;
constexpr int passes = 3;  // digits of the key's top 33 bits: sign, exponent, 21 mantissa bits
constexpr int lowest_shift = 64 - passes * digit_bits;
constexpr std::size_t buckets = std::size_t{1} << digit_bits;

// Stable argsort in linear time: a least-significant-digit radix sort of (key, index) records
// on the top 33 bits of the order key (3 passes of 11 bits, every digit histogram counted in one
// pass), then one insertion pass on the full 64-bit keys. Keys that agree in their top 33 bits
// (values within a relative 2^-21 of each other) are rare and adjacent after the radix passes,
// so the insertion pass is linear in practice; it keeps equal keys in index order. This does half
// the scatter passes of a full 64-bit radix sort.
std::vector<std::uint32_t> radix_argsort(std::span<const double> values) {
  const std::size_t n = values.size();
  // Keys and indices in separate arrays (12 bytes per element and pass instead of a padded
  // 16-byte record); uninitialized, as every element is written before it is read.
  std::unique_ptr<std::uint64_t[]> keys(new std::uint64_t[n]), keys_next(new std::uint64_t[n]);
  std::unique_ptr<std::uint32_t[]> order(new std::uint32_t[n]), order_next(new std::uint32_t[n]);
  std::array<std::array<std::uint32_t, buckets>, passes> counts{};
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t key = order_key(values[i]);
    keys[i] = key;
    order[i] = static_cast<std::uint32_t>(i);
    for (int pass = 0; pass < passes; ++pass) ++counts[pass][(key >> (lowest_shift + pass * digit_bits)) & (buckets - 1)];
  }
  for (int pass = 0; pass < passes; ++pass) {
    auto& count = counts[pass];
    const int shift = lowest_shift + pass * digit_bits;
    if (count[(keys[0] >> shift) & (buckets - 1)] == n) continue;  // one digit value: nothing to do
    std::uint32_t offset = 0;
    for (auto& c : count) offset += std::exchange(c, offset);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t position = count[(keys[i] >> shift) & (buckets - 1)]++;
      keys_next[position] = keys[i];
      order_next[position] = order[i];
    }
    keys.swap(keys_next);
    order.swap(order_next);
  }
  for (std::size_t p = 1; p < n; ++p) {
    if (keys[p - 1] <= keys[p]) continue;
    const std::uint64_t key = keys[p];
    const std::uint32_t index = order[p];
    std::size_t q = p;
    for (; q > 0 && keys[q - 1] > key; --q) {
      keys[q] = keys[q - 1];
      order[q] = order[q - 1];
    }
    keys[q] = key;
    order[q] = index;
  }
  return std::vector<std::uint32_t>(order.get(), order.get() + n);
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
