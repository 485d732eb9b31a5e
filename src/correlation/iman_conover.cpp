#include "growthuq/correlation/iman_conover.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "correlation/score_reordering.hpp"
#include "growthuq/distributions/standard_normal.hpp"
#include "core/avx2_clone.hpp"
#include "core/large_buffer.hpp"
#include "stats/cross_products.hpp"
#include "stats/keyed_sort.hpp"

namespace growthuq {

namespace detail {

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

// The same with the sample of each row as the index: (key(x[i]) << 32) | sample[i].
GROWTHUQ_AVX2_CLONE
void linear_keys(const double* x, std::size_t count, double bound, double scale, const std::uint32_t* sample,
                 std::uint64_t* records) {
  for (std::size_t i = 0; i < count; ++i) {
    const double y = std::min(std::max((x[i] + bound) * scale, 0.0), 4294967295.0) + 0x1.0p52;
    records[i] = (std::bit_cast<std::uint64_t>(y) << 32) | sample[i];
  }
}

}  // namespace

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

std::shared_ptr<const ScoreTable> van_der_waerden_table(std::size_t n) {
  static std::mutex mutex;
  static std::shared_ptr<const ScoreTable> last;
  {
    const std::lock_guard lock(mutex);
    if (last && last->score.size() == n) return last;
  }
  auto table = std::make_shared<ScoreTable>();
  table->score.resize(n);
  fill_van_der_waerden_scores(table->score);
  for (const double x : table->score) table->sum_of_squares += x * x;
  const std::lock_guard lock(mutex);
  last = table;
  return table;
}

ScoreReordering::ScoreReordering(std::vector<const double*> columns, const ScoreTable& table,
                                 const Eigen::LLT<Eigen::MatrixXd>& target)
    : columns_(std::move(columns)), n_(table.score.size()), largest_score_(table.score.empty() ? 0.0 : table.score.back()) {
  const auto m = static_cast<Eigen::Index>(columns_.size());
  Eigen::MatrixXd sample_correlation(m, m);
  sample_correlation = cross_products(columns_, n_) / table.sum_of_squares;
  const Eigen::LLT<Eigen::MatrixXd> sample(sample_correlation);
  if (sample.info() != Eigen::Success) return;
  // M = P Q^-1, from M Q = P  <=>  Q^T M^T = P^T (a triangular solve).
  const Eigen::MatrixXd p = target.matrixL();
  const Eigen::MatrixXd q = sample.matrixL();
  mix_ = q.transpose().triangularView<Eigen::Upper>().solve(p.transpose()).transpose();
  valid_ = true;
}

void ScoreReordering::set_row_order(std::span<const std::uint32_t> sample_of_row,
                                    std::span<const std::uint32_t> row_of_sample) {
  if (sample_of_row.size() != n_ || row_of_sample.size() != n_) {
    throw std::invalid_argument("ScoreReordering::set_row_order: the row order does not have n entries");
  }
  sample_of_row_ = sample_of_row;
  row_of_sample_ = row_of_sample;
}

double ScoreReordering::transformed_score(std::size_t j, std::size_t row) const {
  const auto jj = static_cast<Eigen::Index>(j);
  double x = columns_[j][row] * mix_(jj, jj);
  for (Eigen::Index k = 0; k < jj; ++k) x += mix_(jj, k) * columns_[static_cast<std::size_t>(k)][row];
  return x;
}

void ScoreReordering::sort_column(std::size_t j, std::span<std::uint64_t> records, std::span<std::uint64_t> scratch,
                                  const Run& run) const {
  const auto jj = static_cast<Eigen::Index>(j);
  // The ranks come from records of a 32-bit key linear in the transformed score (key ties are
  // rare and resolved on the scores themselves), never from a stored column of transformed
  // scores. |S*_ij| <= bound, so (x + bound) * scale is in [0, 2^32) (the margin covers
  // rounding); both operations round monotonically, so the key is monotone in x.
  double bound = 0.0;
  for (Eigen::Index k = 0; k <= jj; ++k) bound += std::fabs(mix_(jj, k));
  bound *= (1.0 + 1e-9) * std::fabs(largest_score_);
  const double scale = 0x1.0p32 * (1.0 - 1e-9) / (2.0 * bound);
  const double diagonal = mix_(jj, jj);
  // x a chunk of rows at a time (sequential passes over the score columns vectorize), then keys;
  // the same operations in the same order as transformed_score, so the same bits.
  constexpr std::size_t chunk = 2048;
  double mixed[chunk];
  for (std::size_t first = 0; first < n_; first += chunk) {
    const std::size_t count = std::min(chunk, n_ - first);
    const double* own = columns_[j] + first;
    for (std::size_t i = 0; i < count; ++i) mixed[i] = own[i] * diagonal;
    for (Eigen::Index k = 0; k < jj; ++k) {
      const double factor = mix_(jj, k);
      const double* in = columns_[static_cast<std::size_t>(k)] + first;
      for (std::size_t i = 0; i < count; ++i) mixed[i] += factor * in[i];
    }
    if (sample_of_row_.empty()) {
      linear_keys(mixed, count, bound, scale, first, records.data() + first);
    } else {
      linear_keys(mixed, count, bound, scale, sample_of_row_.data() + first, records.data() + first);
    }
  }
  const auto value = [&](std::uint32_t sample) {
    return transformed_score(j, row_of_sample_.empty() ? sample : row_of_sample_[sample]);
  };
  // 24 sorted key bits: near the centre about 8 n / 2^24 records (0.5 at n = 1e6) share them,
  // and the insertion pass of sort_bucket orders those.
  for_each_sorted_run(records.first(n_), scratch.first(n_), 24, [&](std::size_t first, std::span<std::uint64_t> sorted) {
    order_equal_keys(sorted, value);
    run(first, sorted);
  });
}

}  // namespace detail

std::vector<double> van_der_waerden_scores(std::size_t n) {
  std::vector<double> score(n);
  detail::fill_van_der_waerden_scores(score);
  return score;
}

ImanConoverOutcome iman_conover(std::span<std::vector<std::uint32_t>> ranks, const Eigen::MatrixXd& normal_correlation) {
  const std::size_t m = ranks.size();
  if (normal_correlation.rows() != static_cast<Eigen::Index>(m) || normal_correlation.cols() != static_cast<Eigen::Index>(m)) {
    throw std::invalid_argument("iman_conover: correlation matrix does not match the number of columns");
  }
  if (m < 2) return {true, ""};
  const std::size_t n = ranks[0].size();
  for (const auto& column : ranks) {
    if (column.size() != n) throw std::invalid_argument("iman_conover: columns differ in length");
  }
  if (n <= m) {
    return {false, "a rank correlation between " + std::to_string(m) + " variables cannot be imposed on " +
                       std::to_string(n) + " samples (it needs more samples than variables); the design is uncorrelated"};
  }

  const Eigen::LLT<Eigen::MatrixXd> target(normal_correlation);
  if (target.info() != Eigen::Success) {
    throw std::invalid_argument("iman_conover: target correlation is not positive definite");
  }

  const std::shared_ptr<const detail::ScoreTable> table = detail::van_der_waerden_table(n);
  const double* score = table->score.data();
  detail::LargeBuffer<double> scores(n * m);
  std::vector<const double*> columns;
  for (std::size_t j = 0; j < m; ++j) {
    const std::uint32_t* rank = ranks[j].data();
    double* column = scores.data() + j * n;
    columns.push_back(column);
    // A random gather from an 8n-byte table: prefetching a fixed distance ahead keeps enough
    // cache misses in flight (measured 2-3x faster at n = 1e6 than the plain loop).
    std::size_t i = 0;
    for (; i + detail::prefetch_distance < n; ++i) {
      __builtin_prefetch(score + rank[i + detail::prefetch_distance]);
      column[i] = score[rank[i]];
    }
    for (; i < n; ++i) column[i] = score[rank[i]];
  }
  const detail::ScoreReordering reordering(columns, *table, target);
  if (!reordering.valid()) {
    return {false, "the " + std::to_string(n) + " samples' score correlation is singular; the design is uncorrelated"};
  }
  detail::LargeBuffer<std::uint64_t> records(n), scratch(n);
  for (std::size_t j = 1; j < m; ++j) {
    std::uint32_t* rank = ranks[j].data();
    reordering.sort_column(j, std::span<std::uint64_t>(records.data(), n), std::span<std::uint64_t>(scratch.data(), n),
                           [&](std::size_t first, std::span<const std::uint64_t> sorted) {
                             const std::size_t size = sorted.size();
                             for (std::size_t p = 0; p < size; ++p) {
                               if (p + detail::prefetch_distance < size) {
                                 __builtin_prefetch(rank + detail::record_index(sorted[p + detail::prefetch_distance]), 1);
                               }
                               rank[detail::record_index(sorted[p])] = static_cast<std::uint32_t>(first + p);
                             }
                           });
  }
  return {true, ""};
}

}  // namespace growthuq
