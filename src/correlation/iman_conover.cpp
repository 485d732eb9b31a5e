#include "growthuq/correlation/iman_conover.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include <Eigen/Cholesky>

#include "growthuq/distributions/standard_normal.hpp"
#include "sampling/avx2_clone.hpp"
#include "sampling/large_buffer.hpp"
#include "stats/keyed_sort.hpp"

namespace growthuq {

namespace {

// How many elements ahead random gathers and scatters prefetch.
constexpr std::size_t prefetch_distance = 48;

// records[i] = (key(x[i]) << 32) | (first + i) with key(x) = round((x + bound) scale) clamped to
// [0, 2^32 - 1]. Adding, scaling and rounding to nearest are each monotone, so the key is. The
// rounding adds 2^52 (where a double's unit in the last place is 1) and keeps the low 32 bits,
// which vectorizes where a conversion to a 64-bit integer does not.
GROWTHUQ_AVX2_CLONE
void linear_keys(const double* x, std::size_t count, double bound, double scale, std::size_t first,
                 std::uint64_t* records) {
  for (std::size_t i = 0; i < count; ++i) {
    const double y = std::min(std::max((x[i] + bound) * scale, 0.0), 4294967295.0) + 0x1.0p52;
    records[i] = (std::bit_cast<std::uint64_t>(y) << 32) | (first + i);
  }
}

// score[k] = Phi^-1((k + 1) / (n + 1)), k < n = score.size().
void fill_van_der_waerden_scores(std::span<double> score) {
  const std::size_t n = score.size();
  const double denominator = static_cast<double>(n) + 1.0;
  // Phi^-1 is odd and k/(n+1) is symmetric about 1/2: compute the lower half and mirror it,
  // which also makes the scores sum to zero exactly. The upper half holds the probabilities.
  const std::size_t half = n / 2;
  double* u = score.data() + (n - half);
  for (std::size_t k = 0; k < half; ++k) u[k] = static_cast<double>(k + 1) / denominator;
  standard_normal_quantiles(std::span<const double>(u, half), score.first(half));
  for (std::size_t k = 0; k < half; ++k) score[n - 1 - k] = -score[k];
  if (n % 2 == 1) score[half] = 0.0;
}

}  // namespace

std::vector<double> van_der_waerden_scores(std::size_t n) {
  std::vector<double> score(n);
  fill_van_der_waerden_scores(score);
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

  detail::LargeBuffer<double> score(n);
  fill_van_der_waerden_scores(std::span<double>(score.data(), n));
  const auto rows = static_cast<Eigen::Index>(n);
  detail::LargeBuffer<double> score_storage(n * static_cast<std::size_t>(m));
  Eigen::Map<Eigen::MatrixXd> scores(score_storage.data(), rows, m);
  for (Eigen::Index j = 0; j < m; ++j) {
    const std::uint32_t* rank = ranks[static_cast<std::size_t>(j)].data();
    double* column = scores.col(j).data();
    // A random gather from an 8n-byte table: prefetching a fixed distance ahead keeps enough
    // cache misses in flight (measured 2-3x faster at n = 1e6 than the plain loop).
    std::size_t i = 0;
    for (; i + prefetch_distance < n; ++i) {
      __builtin_prefetch(score.data() + rank[i + prefetch_distance]);
      column[i] = score[rank[i]];
    }
    for (; i < n; ++i) column[i] = score[rank[i]];
  }

  // Every column holds the same scores, so T = S^T S / sum(score^2) is their correlation matrix
  // (the scores have mean zero).
  double sum_of_squares = 0;
  for (std::size_t k = 0; k < n; ++k) sum_of_squares += score[k] * score[k];
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

  // Column j of S* is S_j m_jj + S_0 m_j0 + ... + S_{j-1} m_j,j-1, summed in that order
  // (transformed_score recomputes any element bit for bit). Its ranks come from records of a
  // 32-bit key linear in the score (key ties are rare and resolved on the scores themselves),
  // never from a stored column of transformed scores.
  const auto transformed_score = [&](Eigen::Index j, std::size_t i) {
    const auto row = static_cast<Eigen::Index>(i);
    double x = scores(row, j) * mix(j, j);
    for (Eigen::Index k = 0; k < j; ++k) x += mix(j, k) * scores(row, k);
    return x;
  };
  detail::LargeBuffer<std::uint64_t> records(n), scratch(n);
  const std::span<std::uint64_t> sorted(records.data(), n);
  for (Eigen::Index j = 1; j < m; ++j) {
    // |S*_ij| <= bound, so (x + bound) * scale is in [0, 2^32) (the margin covers rounding);
    // both operations round monotonically, so the key is monotone in x.
    double bound = 0.0;
    for (Eigen::Index k = 0; k <= j; ++k) bound += std::fabs(mix(j, k));
    bound *= (1.0 + 1e-9) * std::fabs(score[n - 1]);
    const double scale = 0x1.0p32 * (1.0 - 1e-9) / (2.0 * bound);
    const double diagonal = mix(j, j);
    // x a chunk of rows at a time (sequential passes over the score columns vectorize), then keys.
    constexpr std::size_t chunk = 2048;
    double mixed[chunk];
    for (std::size_t first = 0; first < n; first += chunk) {
      const std::size_t count = std::min(chunk, n - first);
      const double* own = scores.col(j).data() + first;
      for (std::size_t i = 0; i < count; ++i) mixed[i] = own[i] * diagonal;
      for (Eigen::Index k = 0; k < j; ++k) {
        const double factor = mix(j, k);
        const double* in = scores.col(k).data() + first;
        for (std::size_t i = 0; i < count; ++i) mixed[i] += factor * in[i];
      }
      linear_keys(mixed, count, bound, scale, first, records.data() + first);
    }
    // 24 sorted key bits: near the centre about 8 n / 2^24 records (0.5 at n = 1e6) share them,
    // and the insertion pass of sort_records orders those.
    detail::sort_records(sorted, std::span<std::uint64_t>(scratch.data(), n), 24);
    detail::order_equal_keys(sorted, [&](std::uint32_t i) { return transformed_score(j, i); });
    std::uint32_t* rank = ranks[static_cast<std::size_t>(j)].data();
    std::size_t position = 0;
    for (; position + prefetch_distance < n; ++position) {
      __builtin_prefetch(rank + detail::record_index(records[position + prefetch_distance]), 1);
      rank[detail::record_index(records[position])] = static_cast<std::uint32_t>(position);
    }
    for (; position < n; ++position) rank[detail::record_index(records[position])] = static_cast<std::uint32_t>(position);
  }
  return {true, ""};
}

}  // namespace growthuq
