// Ordinal ranks from 32-bit order-preserving keys, the engine of argsort (ranks.hpp) and of
// Iman-Conover's reordering. A record is (key << 32) | index: sorting records sorts by key and
// breaks key ties by index, so a stable order comes from sorting plain 64-bit integers. Keys
// only need to be monotone (a <= b implies key(a) <= key(b)); runs of equal keys are then put in
// the exact order of the values themselves.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace growthuq::detail {

constexpr std::uint64_t keyed_record(std::uint32_t key, std::uint32_t index) {
  return (std::uint64_t{key} << 32) | index;
}
constexpr std::uint32_t record_index(std::uint64_t record) { return static_cast<std::uint32_t>(record); }
constexpr std::uint32_t record_key(std::uint64_t record) { return static_cast<std::uint32_t>(record >> 32); }

// Sorts `records` ascending: one most-significant-digit radix pass on the key's top 8 bits,
// least-significant-digit passes of 8 bits within each (now cache-resident) bucket down to the
// key's top `radix_bits` bits (16..32), then one insertion pass on whole records, which is linear
// when few records share those bits. `scratch` has records.size() elements; the result is in
// `records`.
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
