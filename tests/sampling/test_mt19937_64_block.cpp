// The fast pieces of a Latin hypercube column against plain references: the block Mersenne
// Twister against std::mt19937_64 and the value [rand.predef] fixes; the batched, prefetching
// shuffle and the branch-free stratum points against the straightforward loops of the scheme
// documented in latin_hypercube.hpp. Equality is exact: the design is pinned bit for bit.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "growthuq/sampling/latin_hypercube.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "sampling/latin_column.hpp"
#include "sampling/mt19937_64_block.hpp"

using namespace growthuq;

namespace {

// The inside-out Fisher-Yates with 32-bit Lemire draws, high half of each 64-bit draw first:
// the scheme of latin_column.hpp, one draw at a time.
std::vector<std::uint32_t> reference_permutation(std::size_t n, std::mt19937_64& engine) {
  std::vector<std::uint32_t> values(n);
  std::uint64_t pair = 0;
  bool has_low = false;
  const auto word = [&]() -> std::uint32_t {
    if (has_low) {
      has_low = false;
      return static_cast<std::uint32_t>(pair);
    }
    pair = engine();
    has_low = true;
    return static_cast<std::uint32_t>(pair >> 32);
  };
  values[0] = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const auto bound = static_cast<std::uint32_t>(i + 1);
    const std::uint32_t threshold = (0u - bound) % bound;
    std::uint64_t product = std::uint64_t{word()} * bound;
    while (static_cast<std::uint32_t>(product) < threshold) product = std::uint64_t{word()} * bound;
    const auto j = static_cast<std::size_t>(product >> 32);
    values[i] = values[j];
    values[j] = static_cast<std::uint32_t>(i);
  }
  return values;
}

// u_k = (k + U_k) / n kept strictly inside stratum k and below 1, one draw per stratum.
double reference_point(std::size_t k, std::size_t n, double offset) {
  const double width = 1.0 / static_cast<double>(n);
  const double lower = static_cast<double>(k) * width;
  const double upper = static_cast<double>(k + 1) * width;
  double u = (static_cast<double>(k) + offset) * width;
  if (u >= upper) u = std::nextafter(upper, 0.0);
  if (u < lower) u = lower;
  if (u > std::nextafter(1.0, 0.0)) u = std::nextafter(1.0, 0.0);
  return u;
}

}  // namespace

TEST_CASE("the block Mersenne Twister is std::mt19937_64") {
  // [rand.predef]: the 10000th consecutive output of a default-constructed (seed 5489)
  // mt19937_64 is 9981545732273789042.
  detail::Mt19937_64Block standard_seed(5489);
  std::uint64_t x = 0;
  for (int i = 0; i < 10000; ++i) x = standard_seed();
  CHECK(x == 9981545732273789042ULL);

  for (const std::uint64_t seed : {std::uint64_t{0}, std::uint64_t{1}, ~std::uint64_t{0}, stream_key(2022, "wild_type", "k")}) {
    detail::Mt19937_64Block block(seed);
    std::mt19937_64 reference(seed);
    for (int i = 0; i < 1000; ++i) REQUIRE(block() == reference());
    // fill() in pieces of awkward sizes continues the same sequence across block boundaries
    for (const std::size_t size : {std::size_t{1}, std::size_t{311}, std::size_t{312}, std::size_t{1000}}) {
      std::vector<std::uint64_t> out(size);
      block.fill(out);
      for (const std::uint64_t value : out) REQUIRE(value == reference());
    }
  }
}

TEST_CASE("the batched shuffle is the documented inside-out Fisher-Yates, draw for draw") {
  for (const std::size_t n : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{64}, std::size_t{65},
                              std::size_t{1000}, std::size_t{100003}}) {
    const std::uint64_t key = stream_key(7, "line", std::to_string(n));
    std::mt19937_64 engine(key);
    const std::vector<std::uint32_t> expected = reference_permutation(n, engine);
    detail::Mt19937_64Block block(key);
    std::vector<std::uint32_t> stratum(n);
    detail::shuffle_strata(stratum, block);
    REQUIRE(stratum == expected);
    // the points then start from a fresh draw (a leftover low half is discarded)
    CHECK(block() == engine());
    // any array is moved exactly like 0, 1, ..., n-1
    std::vector<double> source(n), shuffled(n);
    for (std::size_t i = 0; i < n; ++i) source[i] = 0.5 * static_cast<double>(i) - 3.0;
    detail::Mt19937_64Block again(key);
    detail::shuffled_copy(source, shuffled, again);
    for (std::size_t r = 0; r < n; ++r) REQUIRE(shuffled[r] == source[expected[r]]);
  }
}

TEST_CASE("branch-free stratum points equal the clamped formula, also at the edges of 32-bit n") {
  for (const std::size_t n : {std::size_t{1}, std::size_t{3}, std::size_t{7}, std::size_t{49}, std::size_t{1000},
                              std::size_t{4294967295}}) {
    const std::size_t count = std::min<std::size_t>(n, 3000);
    for (const std::size_t first : {std::size_t{0}, n - count}) {
      const std::uint64_t key = stream_key(3, "points", std::to_string(n));
      std::mt19937_64 engine(key);
      detail::Mt19937_64Block block(key);
      std::vector<double> u(count);
      detail::stratum_points(block, n, first, u, StratumPosition::random);
      for (std::size_t i = 0; i < count; ++i) {
        REQUIRE(u[i] == reference_point(first + i, n, bits_to_open_unit(engine())));
      }
      std::vector<double> centred(count);
      detail::Mt19937_64Block unused(0);
      detail::stratum_points(unused, n, first, centred, StratumPosition::centred);
      for (std::size_t i = 0; i < count; ++i) REQUIRE(centred[i] == reference_point(first + i, n, 0.5));
    }
  }
}
