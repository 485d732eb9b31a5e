// Ordinal ranks from 32-bit order-preserving keys, the engine of argsort (ranks.hpp) and of
// Iman-Conover's reordering. A record is (key << 32) | index: sorting records sorts by key and
// breaks key ties by index, so a stable order comes from sorting plain 64-bit integers. Keys
// only need to be monotone (a <= b implies key(a) <= key(b)); runs of equal keys are then put in
// the exact order of the values themselves.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace growthuq::detail {

constexpr std::uint64_t keyed_record(std::uint32_t key, std::uint32_t index) {
  return (std::uint64_t{key} << 32) | index;
}
constexpr std::uint32_t record_index(std::uint64_t record) { return static_cast<std::uint32_t>(record); }
constexpr std::uint32_t record_key(std::uint64_t record) { return static_cast<std::uint32_t>(record >> 32); }

// A 64-bit key whose order is the order of the doubles (no NaN): the IEEE-754 bits with the sign
// bit flipped for positives and all bits flipped for negatives; +0.0 and -0.0 get the same key.
inline std::uint64_t order_key64(double value) {
  const auto bits = std::bit_cast<std::uint64_t>(value + 0.0);
  return (bits >> 63) != 0 ? ~bits : bits | (std::uint64_t{1} << 63);
}

// Its top 32 bits (sign, exponent, 20 mantissa bits): doubles within a relative 2^-20 may share
// a key, which order_equal_keys sorts out.
inline std::uint32_t order_key32(double value) { return static_cast<std::uint32_t>(order_key64(value) >> 32); }

// The 32 bits of order_key64 that tell a given set of doubles apart best: (key - lowest) >>
// shift, where shift drops only the bits that the set's range of keys does not need. Data in a
// few binades then get about 29 mantissa bits instead of 20, so far fewer keys tie (and fewer
// values must be compared to order them). Monotone: subtraction and shift keep the order.
struct RangeKey {
  std::uint64_t lowest = 0;
  int shift = 32;
  RangeKey(std::uint64_t lowest_key, std::uint64_t highest_key) : lowest(lowest_key), shift(0) {
    const std::uint64_t span = highest_key - lowest_key;
    while (shift < 64 && (span >> shift) > 0xffffffffULL) ++shift;
  }
  std::uint32_t operator()(double value) const { return static_cast<std::uint32_t>((order_key64(value) - lowest) >> shift); }
};

// The sort in two halves, so a caller can consume the sorted records bucket by bucket while
// they are still in cache (no pass over the whole sorted array):
//   top_bucket_partition: one most-significant-digit pass on the records' top 8 bits (the only
//     pass that streams the whole array through memory), stable, from `records` into `scratch`;
//     returns the 257 bucket starts (bucket b is [start[b], start[b + 1]) of `scratch`).
//   sort_bucket: sorts one bucket, now small enough for L1/L2, by least-significant-digit
//     passes of 8 bits on the key's next bits down to its top `radix_bits` bits (16..32), then
//     one insertion pass on whole records, which is linear when few records share those bits.
//     `other` is a free area of the same size, best one that stays in cache from bucket to
//     bucket (writing to memory not in cache made the passes 3x slower, measured); returns
//     where the sorted bucket is (data or other).
// Every pass is stable, so records equal in the sorted bits stay in index order.
std::vector<std::size_t> top_bucket_partition(std::span<const std::uint64_t> records, std::span<std::uint64_t> scratch);
std::uint64_t* sort_bucket(std::uint64_t* data, std::uint64_t* other, std::size_t size, int radix_bits);

// Sorts `records` and hands them to `run(first_position, sorted_records)` in ascending order,
// one top-level bucket at a time (a run holds the records of sorted positions first_position,
// first_position + 1, ... and may be reordered by `run`). `scratch` has records.size()
// elements and holds every run at its position in the end; `records` is overwritten. Equal
// keys never straddle two runs.
template <class Run>
void for_each_sorted_run(std::span<std::uint64_t> records, std::span<std::uint64_t> scratch, int radix_bits, Run&& run) {
  if (records.empty()) return;
  const std::vector<std::size_t> start = top_bucket_partition(records, scratch);
  // The front of `records` (free after the partition) is every bucket's working room, so it
  // stays in cache.
  std::uint64_t* other = records.data();
  for (std::size_t b = 0; b + 1 < start.size(); ++b) {
    const std::size_t size = start[b + 1] - start[b];
    if (size == 0) continue;
    std::uint64_t* sorted = sort_bucket(scratch.data() + start[b], other, size, radix_bits);
    if (sorted == other) {
      std::copy_n(other, size, scratch.data() + start[b]);
      sorted = scratch.data() + start[b];
    }
    run(start[b], std::span<std::uint64_t>(sorted, size));
  }
}

// Sorts `records` ascending (the result in `records`); `scratch` has records.size() elements.
void sort_records(std::span<std::uint64_t> records, std::span<std::uint64_t> scratch, int radix_bits);

// Puts every run of equal keys in sorted `records` in ascending order of value(index), ties
// kept in index order (the stable order of the values). value(i) must be monotone with the key.
template <class Value>
void order_equal_keys(std::span<std::uint64_t> records, const Value& value) {
  const std::size_t n = records.size();
  std::size_t first = 0;
  while (first < n) {
    std::size_t last = first + 1;
    while (last < n && record_key(records[last]) == record_key(records[first])) ++last;
    for (std::size_t p = first + 1; p < last; ++p) {
      const std::uint64_t record = records[p];
      const double x = value(record_index(record));
      std::size_t q = p;
      for (; q > first && value(record_index(records[q - 1])) > x; --q) records[q] = records[q - 1];
      records[q] = record;
    }
    first = last;
  }
}

}  // namespace growthuq::detail
