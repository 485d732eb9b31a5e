// Iman & Conover (1982, "A distribution-free approach to inducing rank correlation among input
// variables", Commun. Statist. B11:311-334): impose a rank correlation on a Latin hypercube
// design by reordering each column only, so every stratum keeps exactly one point.
// Works on ranks: ranks[j][i] is the 0-based rank (= stratum) of sample i in variable j.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace growthuq {

// van der Waerden scores Phi^-1(k / (n + 1)), k = 1..n (increasing, antisymmetric).
std::vector<double> van_der_waerden_scores(std::size_t n);

struct ImanConoverOutcome {
  bool imposed = false;
  std::string message;  // why not, when not imposed
};

// Reorders `ranks` (m columns, each a permutation of 0..n-1) so that the Pearson correlation of
// their van der Waerden scores equals `normal_correlation` (m x m, positive definite; see
// rank_correlation_target.hpp for the conversion from a Spearman target):
//   S[i][j] = score[ranks[j][i]];  T = corr(S) = Q Q^T;  R = P P^T;  S* = S (P Q^-1)^T;
//   new ranks[j] = ordinal ranks of column j of S*.
// P Q^-1 is lower triangular with a positive diagonal, so column 0 keeps its order and is not
// sorted. When n <= m, or the sample's score correlation T is singular, nothing is changed and
// the outcome says why.
ImanConoverOutcome iman_conover(std::span<std::vector<std::uint32_t>> ranks, const Eigen::MatrixXd& normal_correlation);

}  // namespace growthuq
