#include "growthuq/correlation/iman_conover.hpp"

#include <stdexcept>

#include <Eigen/Cholesky>

#include "growthuq/distributions/standard_normal.hpp"
#include "growthuq/stats/ranks.hpp"

namespace growthuq {

std::vector<double> van_der_waerden_scores(std::size_t n) {
  std::vector<double> score(n);
  const double denominator = static_cast<double>(n) + 1.0;
  // Phi^-1 is odd and k/(n+1) is symmetric about 1/2: compute the lower half and mirror it,
  // which also makes the scores sum to zero exactly.
  const std::size_t half = n / 2;
  std::vector<double> u(half);
  for (std::size_t k = 0; k < half; ++k) u[k] = static_cast<double>(k + 1) / denominator;
  standard_normal_quantiles(u, std::span<double>(score.data(), half));
  for (std::size_t k = 0; k < half; ++k) score[n - 1 - k] = -score[k];
  if (n % 2 == 1) score[half] = 0.0;
  return score;
}

ImanConoverOutcome iman_conover(std::span<std::vector<std::uint32_t>> ranks, const Eigen::MatrixXd& normal_correlation) {
  const auto m = static_cast<Eigen::Index>(ranks.size());
  if (normal_correlation.rows() != m || normal_correlation.cols() != m) {
    throw std::invalid_argument("iman_conover: correlation matrix does not match the number of columns");
  }
  if (m < 2) return {true, ""};
  const std::size_t n = ranks[0].size();
  for (const auto& column : ranks) {
    if (column.size() != n) throw std::invalid_argument("iman_conover: columns differ in length");
  }
  if (n <= static_cast<std::size_t>(m)) {
    return {false, "a rank correlation between " + std::to_string(m) + " variables cannot be imposed on " +
                       std::to_string(n) + " samples (it needs more samples than variables); the design is uncorrelated"};
  }

  const Eigen::LLT<Eigen::MatrixXd> target(normal_correlation);
  if (target.info() != Eigen::Success) {
    throw std::invalid_argument("iman_conover: target correlation is not positive definite");
  }

  const std::vector<double> score = van_der_waerden_scores(n);
  const auto rows = static_cast<Eigen::Index>(n);
  Eigen::MatrixXd scores(rows, m);
  for (Eigen::Index j = 0; j < m; ++j) {
    const std::uint32_t* rank = ranks[static_cast<std::size_t>(j)].data();
    double* column = scores.col(j).data();
    for (std::size_t i = 0; i < n; ++i) column[i] = score[rank[i]];
  }

  // Every column holds the same scores, so T = S^T S / sum(score^2) is their correlation matrix
  // (the scores have mean zero).
  double sum_of_squares = 0;
  for (const double s : score) sum_of_squares += s * s;
  Eigen::MatrixXd sample_correlation(m, m);
  sample_correlation.triangularView<Eigen::Lower>() = scores.transpose() * scores / sum_of_squares;
  const Eigen::LLT<Eigen::MatrixXd> sample(sample_correlation);
  if (sample.info() != Eigen::Success) {
    return {false, "the " + std::to_string(n) + " samples' score correlation is singular; the design is uncorrelated"};
  }
  // M = P Q^-1, from M Q = P  <=>  Q^T M^T = P^T (a triangular solve).
  const Eigen::MatrixXd p = target.matrixL();
  const Eigen::MatrixXd q = sample.matrixL();
  const Eigen::MatrixXd mix = q.transpose().triangularView<Eigen::Upper>().solve(p.transpose()).transpose();

  // Transform in place from the last column down: column j of S* needs columns 0..j of S.
  for (Eigen::Index j = m - 1; j >= 1; --j) {
    double* out = scores.col(j).data();
    for (std::size_t i = 0; i < n; ++i) out[i] *= mix(j, j);
    for (Eigen::Index k = 0; k < j; ++k) {
      const double factor = mix(j, k);
      const double* in = scores.col(k).data();
      for (std::size_t i = 0; i < n; ++i) out[i] += factor * in[i];
    }
    const std::vector<std::uint32_t> order = argsort(std::span<const double>(out, n));
    std::uint32_t* rank = ranks[static_cast<std::size_t>(j)].data();
    for (std::size_t position = 0; position < n; ++position) rank[order[position]] = static_cast<std::uint32_t>(position);
  }
  return {true, ""};
}

}  // namespace growthuq
