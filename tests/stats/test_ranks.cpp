// Ranks and argsort: small hand-checked cases, scipy's rankdata, and the radix path against
// std::stable_sort on large inputs with ties, signed zeros, negatives, subnormals and values
// that differ only in the low bits the radix passes skip.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/ranks.hpp"

using namespace growthuq;

TEST_CASE("average ranks match scipy.stats.rankdata") {
  // /usr/bin/python3 -c "import scipy.stats as st; print(st.rankdata([1,2,2,3,5,4]))"
  const std::vector<double> values{1, 2, 2, 3, 5, 4};
  CHECK(average_ranks(values) == std::vector<double>{1.0, 2.5, 2.5, 4.0, 6.0, 5.0});
  CHECK(ordinal_ranks(values) == std::vector<std::uint32_t>{0, 1, 2, 3, 5, 4});
}

TEST_CASE("radix argsort equals a stable comparison sort") {
  for (const std::size_t n : {std::size_t{1023}, std::size_t{1024}, std::size_t{5000}, std::size_t{200000}}) {
    RandomStream stream(derive_key(42, "argsort"));
    std::vector<double> values(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double u = stream.uniform();
      // a mix of normal-looking values, exact ties, both zeros, tiny and huge magnitudes
      switch (stream.below(7)) {
        case 5: values[i] = 1.0 + std::floor(1000 * u) * 0x1.0p-40; break;  // equal in the top 33 key bits
        case 0: values[i] = std::floor(10 * u) - 5; break;
        case 1: values[i] = (u < 0.5) ? -0.0 : 0.0; break;
        case 2: values[i] = (u - 0.5) * 1e-310; break;
        case 3: values[i] = (u - 0.5) * 1e300; break;
        default: values[i] = std::log(u / (1 - u)); break;
      }
    }
    std::vector<std::uint32_t> expected(n);
    std::iota(expected.begin(), expected.end(), std::uint32_t{0});
    std::stable_sort(expected.begin(), expected.end(), [&](auto a, auto b) { return values[a] < values[b]; });
    CHECK(argsort(values) == expected);
    const std::vector<std::uint32_t> rank = ordinal_ranks(values);
    for (std::size_t p = 0; p < n; ++p) REQUIRE(rank[expected[p]] == p);
  }
}
