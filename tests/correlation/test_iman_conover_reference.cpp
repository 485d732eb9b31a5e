// Iman-Conover's fast path (32-bit linear keys, MSD/LSD radix sort, key ties resolved on
// recomputed scores) against the textbook steps of iman_conover.hpp done the plain way: the
// score matrix materialized, S* = S (P Q^-1)^T, and std::stable_sort of every column. The ranks
// must be identical, not just close: a design is pinned bit for bit by its seed.
#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include <Eigen/Cholesky>

#include "growthuq/correlation/iman_conover.hpp"
#include "growthuq/correlation/rank_correlation_target.hpp"
#include "growthuq/sampling/latin_hypercube.hpp"
#include "growthuq/sampling/random_stream.hpp"

using namespace growthuq;

namespace {

std::vector<std::vector<std::uint32_t>> reference_iman_conover(std::vector<std::vector<std::uint32_t>> ranks,
                                                               const Eigen::MatrixXd& normal_correlation) {
  const std::size_t n = ranks[0].size();
  const auto m = static_cast<Eigen::Index>(ranks.size());
  const std::vector<double> score = van_der_waerden_scores(n);
  Eigen::MatrixXd s(static_cast<Eigen::Index>(n), m);
  for (Eigen::Index j = 0; j < m; ++j) {
    for (std::size_t i = 0; i < n; ++i) s(static_cast<Eigen::Index>(i), j) = score[ranks[static_cast<std::size_t>(j)][i]];
  }
  double sum_of_squares = 0;
  for (const double x : score) sum_of_squares += x * x;
  Eigen::MatrixXd t(m, m);
  t.triangularView<Eigen::Lower>() = s.transpose() * s / sum_of_squares;
  const Eigen::MatrixXd p = Eigen::LLT<Eigen::MatrixXd>(normal_correlation).matrixL();
  const Eigen::MatrixXd q = Eigen::LLT<Eigen::MatrixXd>(t).matrixL();
  const Eigen::MatrixXd mix = q.transpose().triangularView<Eigen::Upper>().solve(p.transpose()).transpose();
  for (Eigen::Index j = 1; j < m; ++j) {
    std::vector<double> x(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto row = static_cast<Eigen::Index>(i);
      x[i] = s(row, j) * mix(j, j);
      for (Eigen::Index k = 0; k < j; ++k) x[i] += mix(j, k) * s(row, k);
    }
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), std::uint32_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return x[a] < x[b]; });
    for (std::size_t position = 0; position < n; ++position) {
      ranks[static_cast<std::size_t>(j)][order[position]] = static_cast<std::uint32_t>(position);
    }
  }
  return ranks;
}

}  // namespace

TEST_CASE("Iman-Conover's ranks equal a plain stable sort of the transformed scores") {
  Eigen::MatrixXd spearman(4, 4);
  spearman << 1.0, 0.25, 0.55, 0.30,  //
      0.25, 1.0, -0.10, 0.05,         //
      0.55, -0.10, 1.0, 0.70,         //
      0.30, 0.05, 0.70, 1.0;
  const ImanConoverTarget target = make_iman_conover_target(spearman, {"k", "h", "d", "d0"}, "test");
  // n = 5 and 6 give many exactly tied transformed scores (few distinct score combinations)
  for (const std::size_t n : {std::size_t{5}, std::size_t{6}, std::size_t{50}, std::size_t{1000}, std::size_t{4099},
                              std::size_t{200000}}) {
    std::vector<std::vector<std::uint32_t>> ranks;
    for (int j = 0; j < 4; ++j) {
      ranks.push_back(latin_hypercube_column(n, stream_key(11, "reference", std::to_string(j)), StratumPosition::centred).stratum);
    }
    const auto expected = reference_iman_conover(ranks, target.normal_correlation);
    REQUIRE(iman_conover(ranks, target.normal_correlation).imposed);
    for (std::size_t j = 0; j < 4; ++j) REQUIRE(ranks[j] == expected[j]);
  }
}
