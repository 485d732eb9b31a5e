// The reordering step of Iman-Conover (iman_conover.hpp) on a matrix of van der Waerden scores
// that the caller has built, handing out the new order as it is found. The line design builds
// the score columns by shuffling the scores themselves and turns the order straight into values,
// so no rank column is gathered from or written in between.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace growthuq::detail {

// score[k] = Phi^-1((k + 1) / (n + 1)), k < n = score.size(): increasing, antisymmetric
// (score[n - 1 - k] = -score[k] exactly), so the scores sum to zero exactly.
void fill_van_der_waerden_scores(std::span<double> score);

class ScoreReordering {
 public:
  // `scores` is n x m, column-major: column j holds variable j's scores in sample order, a
  // permutation of the n van der Waerden scores, whose sum of squares is `sum_of_squares` and
  // whose largest is `largest_score`. `target` factors the normal-score target R = P P^T.
  // Computes T = S^T S / sum_of_squares = Q Q^T and the lower triangular mix M = P Q^-1.
  ScoreReordering(std::span<const double> scores, std::size_t n, std::size_t m, double sum_of_squares,
                  double largest_score, const Eigen::LLT<Eigen::MatrixXd>& target);

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

  std::span<const double> scores_;
  std::span<const std::uint32_t> sample_of_row_, row_of_sample_;  // empty: row = sample
  std::size_t n_;
  double largest_score_;
  Eigen::MatrixXd mix_;
  bool valid_ = false;
};

}  // namespace growthuq::detail
