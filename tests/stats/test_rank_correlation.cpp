// Spearman matrices against scipy.stats.spearmanr, and the rank-difference formula against the
// general (average-rank Pearson) one on tie-free data.
#include <doctest/doctest.h>

#include <numeric>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/rank_correlation.hpp"
#include "growthuq/stats/ranks.hpp"

using namespace growthuq;

TEST_CASE("Spearman matrix with ties equals scipy") {
  // /usr/bin/python3 -c "import numpy as np, scipy.stats as st; a=[1,2,2,3,5,4]; b=[2,1,4,3,6,6];
  //   c=[9,7,7,1,0,3]; print(st.spearmanr(np.c_[a,b,c]).correlation.tolist())"
  const std::vector<double> a{1, 2, 2, 3, 5, 4}, b{2, 1, 4, 3, 6, 6}, c{9, 7, 7, 1, 0, 3};
  const Eigen::MatrixXd s = spearman_matrix({a, b, c});
  // Tolerance: a few ulps of rounding in sums of six terms.
  CHECK(s(0, 1) == doctest::Approx(0.7941176470588236).epsilon(1e-14));
  CHECK(s(0, 2) == doctest::Approx(-0.9411764705882354).epsilon(1e-14));
  CHECK(s(1, 2) == doctest::Approx(-0.6470588235294118).epsilon(1e-14));
  CHECK(s(2, 1) == s(1, 2));
  CHECK(s(1, 1) == 1.0);
}

TEST_CASE("rank-difference formula equals the general Spearman without ties") {
  const std::size_t n = 3001;
  RandomStream stream(derive_key(7, "spearman"));
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = stream.uniform();
    y[i] = x[i] + stream.uniform();
  }
  const std::vector<std::uint32_t> rx = ordinal_ranks(x), ry = ordinal_ranks(y);
  const Eigen::MatrixXd general = spearman_matrix({x, y});
  const Eigen::MatrixXd from_ranks = spearman_matrix_of_ranks({rx, ry});
  CHECK(general(0, 1) > 0.5);
  CHECK(from_ranks(0, 1) == doctest::Approx(general(0, 1)).epsilon(1e-12));
}

TEST_CASE("Spearman rejects what has no rank correlation") {
  const std::vector<double> a{1, 2, 3}, constant{2, 2, 2}, shorter{1, 2}, with_nan{1, std::nan(""), 3};
  CHECK_THROWS_WITH_AS(spearman_matrix({a, constant}), "rank correlation: column 2 is constant: its rank correlation is undefined", InputError);
  CHECK_THROWS_AS(spearman_matrix({a, shorter}), InputError);
  CHECK_THROWS_AS(spearman_matrix({a, with_nan}), InputError);
  CHECK_THROWS_AS(spearman_matrix({std::span<const double>(a.data(), 1)}), InputError);
}
