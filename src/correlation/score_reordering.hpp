// The reordering step of Iman-Conover (iman_conover.hpp) on a matrix of van der Waerden scores
// that the caller has built, handing out the new order as it is found. The line design builds
// the score columns by shuffling the scores themselves and turns the order straight into values,
// so no rank column is gathered from or written in between.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "growthuq/core/large_vector.hpp"

namespace growthuq::detail {

// score[k] = Phi^-1((k + 1) / (n + 1)), k < n = score.size(): increasing, antisymmetric
// (score[n - 1 - k] = -score[k] exactly), so the scores sum to zero exactly.
void fill_van_der_waerden_scores(std::span<double> score);

// The n van der Waerden scores with their sum of squares, computed once per n: the lines of a
// campaign share n, and so do the repetitions of a benchmark. The last table is kept.
struct ScoreTable {
  LargeVector<double> score;
  double sum_of_squares = 0;
};
std::shared_ptr<const ScoreTable> van_der_waerden_table(std::size_t n);

class ScoreReordering {
 public:
  // `columns[j]` holds variable j's n scores in sample order, a permutation of the table's
  // scores. `target` factors the normal-score target R = P P^T. Computes T = S^T S /
  // sum(score^2) = Q Q^T (the scores have mean zero) and the lower triangular mix M = P Q^-1.
  ScoreReordering(std::vector<const double*> columns, const ScoreTable& table, const Eigen::LLT<Eigen::MatrixXd>& target);

  // False when the sample's score correlation T is singular: nothing can be imposed.
  bool valid() const { return valid_; }

  // Where the rows of `scores` go: by default row r is sample r. A design may hold its rows in
  // another order (sample_of_row[r] is the sample of row r, row_of_sample its inverse); both
  // must outlive the calls to sort_column.
  void set_row_order(std::span<const std::uint32_t> sample_of_row, std::span<const std::uint32_t> row_of_sample);

  // Sorted column j >= 1 of S* = S M^T: records (key << 32 | sample) in ascending order of the
  // transformed score, ties in sample order, handed to run(first_position, records) one run of
  // consecutive positions at a time (keyed_sort.hpp). records and scratch hold n elements.
  using Run = std::function<void(std::size_t first_position, std::span<const std::uint64_t> sorted)>;
  void sort_column(std::size_t j, std::span<std::uint64_t> records, std::span<std::uint64_t> scratch, const Run& run) const;

 private:
  // Element (r, j) of S*: S_rj m_jj + S_r0 m_j0 + ... + S_r,j-1 m_j,j-1, summed in that order.
  double transformed_score(std::size_t j, std::size_t row) const;

  std::vector<const double*> columns_;
  std::span<const std::uint32_t> sample_of_row_, row_of_sample_;  // empty: row = sample
  std::size_t n_;
  double largest_score_;
  Eigen::MatrixXd mix_;
  bool valid_ = false;
};

}  // namespace growthuq::detail
