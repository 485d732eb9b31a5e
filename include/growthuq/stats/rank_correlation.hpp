// Spearman rank correlation of several columns: the Pearson correlation of their average ranks
// (Spearman 1904), so ties are handled. Used to report the correlation a design achieved and by
// `growthuq correlate`.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace growthuq {

// The m x m Spearman matrix of m columns of equal length n >= 2. InputError (location
// "rank correlation") when lengths differ, n < 2, a value is NaN, or a column is constant (its
// correlation is undefined).
Eigen::MatrixXd spearman_matrix(const std::vector<std::span<const double>>& columns);

// The same from 0-based ordinal ranks without ties (each column a permutation of 0..n-1), as a
// Latin hypercube design holds them: rho_s = 1 - 6 sum d^2 / (n (n^2 - 1)), exact in that case.
Eigen::MatrixXd spearman_matrix_of_ranks(const std::vector<std::span<const std::uint32_t>>& ranks);

}  // namespace growthuq
