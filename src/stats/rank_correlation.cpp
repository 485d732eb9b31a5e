#include "growthuq/stats/rank_correlation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/stats/ranks.hpp"

namespace growthuq {

namespace {

constexpr const char* location = "rank correlation";

}  // namespace

Eigen::MatrixXd spearman_matrix(const std::vector<std::span<const double>>& columns) {
  const std::size_t m = columns.size();
  const std::size_t n = m > 0 ? columns[0].size() : 0;
  if (n < 2) throw InputError(location, "needs at least 2 samples per column, got " + std::to_string(n));
  // Centred average ranks, one column each: the Pearson correlation of ranks is Spearman's rho.
  Eigen::MatrixXd centred(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
  for (std::size_t j = 0; j < m; ++j) {
    if (columns[j].size() != n) {
      throw InputError(location, "column " + std::to_string(j + 1) + " has " + std::to_string(columns[j].size()) +
                                     " values: expected " + std::to_string(n) + " like the first");
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (std::isnan(columns[j][i])) {
        throw InputError(location, "column " + std::to_string(j + 1) + " row " + std::to_string(i + 1) + " is NaN");
      }
    }
    const std::vector<double> rank = average_ranks(columns[j]);
    const double mean = 0.5 * static_cast<double>(n + 1);
    for (std::size_t i = 0; i < n; ++i) centred(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = rank[i] - mean;
  }
  const Eigen::MatrixXd products = centred.transpose() * centred;
  const Eigen::VectorXd scale = products.diagonal().cwiseSqrt();
  for (std::size_t j = 0; j < m; ++j) {
    if (!(scale(static_cast<Eigen::Index>(j)) > 0)) {
      throw InputError(location, "column " + std::to_string(j + 1) + " is constant: its rank correlation is undefined");
    }
  }
  Eigen::MatrixXd result = products.array() / (scale * scale.transpose()).array();
  result.diagonal().setOnes();
  return result;
}

Eigen::MatrixXd spearman_matrix_of_ranks(const std::vector<std::span<const std::uint32_t>>& ranks) {
  const auto m = static_cast<Eigen::Index>(ranks.size());
  const std::size_t n = ranks.empty() ? 0 : ranks[0].size();
  if (n < 2) throw InputError(location, "needs at least 2 samples per column, got " + std::to_string(n));
  for (const auto& column : ranks) {
    if (column.size() != n) throw InputError(location, "rank columns differ in length");
  }
  Eigen::MatrixXd result = Eigen::MatrixXd::Identity(m, m);
  const double nd = static_cast<double>(n);
  for (Eigen::Index a = 0; a < m; ++a) {
    for (Eigen::Index b = a + 1; b < m; ++b) {
      // Sum of squared rank differences: exact integer sums over blocks short enough not to
      // overflow 64 bits (block * (n - 1)^2 < 2^64), then added in double.
      const std::size_t block = static_cast<std::size_t>(std::clamp(1.8e19 / (nd * nd), 1.0, 65536.0));
      const std::uint32_t* ra = ranks[static_cast<std::size_t>(a)].data();
      const std::uint32_t* rb = ranks[static_cast<std::size_t>(b)].data();
      double total = 0;
      for (std::size_t start = 0; start < n; start += block) {
        const std::size_t end = std::min(n, start + block);
        std::uint64_t block_sum = 0;
        for (std::size_t i = start; i < end; ++i) {
          const auto d = static_cast<std::int64_t>(ra[i]) - static_cast<std::int64_t>(rb[i]);
          block_sum += static_cast<std::uint64_t>(d * d);
        }
        total += static_cast<double>(block_sum);
      }
      const double rho = 1.0 - 6.0 * total / (nd * (nd * nd - 1.0));
      result(a, b) = result(b, a) = rho;
    }
  }
  return result;
}

}  // namespace growthuq
