// The pool behind LargeVector and the scratch buffers: a released large block serves the next
// request of about its size (the point: pages already mapped), not one much smaller, and
// vectors on it behave as vectors.
#include <doctest/doctest.h>

#include <numeric>

#include "growthuq/core/large_vector.hpp"

using namespace growthuq;

TEST_CASE("a released large block is handed out again for a request of about its size") {
  detail::release_cached_blocks();
  constexpr std::size_t mib = std::size_t{1} << 20;
  void* block = detail::acquire_block(8 * mib);
  detail::release_block(block, 8 * mib);
  // 4 MiB is less than 8 MiB / 1.25: a fresh block, not the kept one.
  void* smaller = detail::acquire_block(4 * mib);
  CHECK(smaller != block);
  // 7 MiB fits in the kept 8 MiB block, which is at most a quarter larger.
  void* similar = detail::acquire_block(7 * mib);
  CHECK(similar == block);
  detail::release_block(smaller, 4 * mib);
  detail::release_block(similar, 7 * mib);
  // Below 1 MiB nothing is kept: plain malloc and free.
  void* small = detail::acquire_block(1000);
  detail::release_block(small, 1000);
  detail::release_cached_blocks();
}

TEST_CASE("LargeVector holds what is written to it") {
  LargeVector<double> values;
  values.resize(3'000'000);
  std::iota(values.begin(), values.end(), 0.0);
  const LargeVector<double> copy = values;
  CHECK(copy.size() == 3'000'000);
  CHECK(copy[2'999'999] == 2'999'999.0);
  values.assign(5, 1.5);
  CHECK(values == LargeVector<double>{1.5, 1.5, 1.5, 1.5, 1.5});
}
