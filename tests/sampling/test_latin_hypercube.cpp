// Latin hypercube columns: one point in every stratum (exact, in double precision), the stratum
// of each sample is its rank, centred points sit at the midpoints.
#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

#include "growthuq/sampling/latin_hypercube.hpp"
#include "growthuq/sampling/random_stream.hpp"

using namespace growthuq;

namespace {

// Every stratum [edge(k), edge(k+1)) holds exactly one of the points, and sample i's point is in
// stratum[i].
void check_one_point_per_stratum(const LatinColumn& column, std::size_t n) {
  REQUIRE(column.stratum.size() == n);
  REQUIRE(column.u_by_stratum.size() == n);
  std::vector<int> hits(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t k = column.stratum[i];
    REQUIRE(k < n);
    ++hits[k];
    const double u = column.u_by_stratum[k];
    REQUIRE(u >= stratum_edge(k, n));
    REQUIRE(u < stratum_edge(k + 1, n));
    REQUIRE(u > 0.0);
    REQUIRE(u < 1.0);
  }
  CHECK(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }));
}

}  // namespace

TEST_CASE("every stratum holds exactly one point") {
  for (const std::size_t n : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{10}, std::size_t{1000},
                              std::size_t{100003}}) {
    for (const auto position : {StratumPosition::random, StratumPosition::centred}) {
      CAPTURE(n);
      check_one_point_per_stratum(latin_hypercube_column(n, stream_key(1, "line", "k"), position), n);
    }
  }
}

TEST_CASE("centred points are the strata midpoints; the permutation does not depend on the position") {
  const std::size_t n = 8;
  const LatinColumn centred = latin_hypercube_column(n, 77, StratumPosition::centred);
  const LatinColumn random = latin_hypercube_column(n, 77, StratumPosition::random);
  for (std::size_t k = 0; k < n; ++k) CHECK(centred.u_by_stratum[k] == (static_cast<double>(k) + 0.5) / 8.0);
  CHECK(centred.stratum == random.stratum);
  CHECK(latin_hypercube_column(n, 78, StratumPosition::random).stratum != random.stratum);
}

TEST_CASE("the permutation is uniform: each sample's stratum is equally likely") {
  // Over 6000 keys, sample 0 of a 3-sample column lands in each stratum ~2000 times; chi-square
  // with 2 degrees of freedom, 99.9 % quantile 13.8.
  std::vector<int> counts(3, 0);
  for (std::uint64_t key = 0; key < 6000; ++key) ++counts[latin_hypercube_column(3, key, StratumPosition::random).stratum[0]];
  double chi2 = 0;
  for (const int c : counts) chi2 += (c - 2000.0) * (c - 2000.0) / 2000.0;
  CHECK(chi2 < 13.8);
}
