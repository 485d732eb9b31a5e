#include "stats/keyed_sort.hpp"

#include <algorithm>
#include <utility>

namespace growthuq::detail {

namespace {

constexpr int top_bits = 8;
constexpr std::size_t top_buckets = std::size_t{1} << top_bits;
constexpr std::size_t small_bucket = 48;  // insertion sort alone is faster below this

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

}  // namespace

std::vector<std::size_t> top_bucket_partition(std::span<const std::uint64_t> records, std::span<std::uint64_t> scratch) {
  std::vector<std::size_t> start(top_buckets + 1, 0);
  for (const std::uint64_t record : records) ++start[(record >> (64 - top_bits)) + 1];
  for (std::size_t b = 0; b < top_buckets; ++b) start[b + 1] += start[b];
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (const std::uint64_t record : records) scratch[next[record >> (64 - top_bits)]++] = record;
  return start;
}

std::uint64_t* sort_bucket(std::uint64_t* data, std::uint64_t* other, std::size_t size, int radix_bits) {
  if (size > small_bucket) {
    // LSD passes on the 8-bit digits below the top byte, down to the key's top radix_bits bits.
    const int passes = std::clamp((radix_bits - top_bits + 7) / 8, 0, 3);
    int shifts[3];
    for (int pass = 0; pass < passes; ++pass) shifts[pass] = 64 - top_bits - 8 * (passes - pass);
    std::uint32_t count[3][256] = {};
    for (std::size_t i = 0; i < size; ++i) {
      for (int pass = 0; pass < passes; ++pass) ++count[pass][(data[i] >> shifts[pass]) & 255];
    }
    for (int pass = 0; pass < passes; ++pass) {
      if (count[pass][(data[0] >> shifts[pass]) & 255] == size) continue;  // one digit value: nothing moves
      std::uint32_t offset = 0;
      for (auto& c : count[pass]) offset += std::exchange(c, offset);
      for (std::size_t i = 0; i < size; ++i) other[count[pass][(data[i] >> shifts[pass]) & 255]++] = data[i];
      std::swap(data, other);
    }
  }
  insertion_sort(data, size);
  return data;
}

void sort_records(std::span<std::uint64_t> records, std::span<std::uint64_t> scratch, int radix_bits) {
  if (records.size() < 2) return;
  for_each_sorted_run(records, scratch, radix_bits, [](std::size_t, std::span<std::uint64_t>) {});
  std::copy(scratch.begin(), scratch.begin() + static_cast<std::ptrdiff_t>(records.size()), records.begin());
}

}  // namespace growthuq::detail
