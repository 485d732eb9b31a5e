// A Spearman rank-correlation target as Iman-Conover needs it: validated, converted to the
// correlation of normal scores, and repaired to the nearest correlation matrix when that is not
// positive definite (Eqs. (C1), (C4), src/correlation/README.md).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace growthuq {

// InputError at `location` unless `spearman` is square, symmetric (to 1e-12), has entries in
// [-1, 1] and a unit diagonal. `names` label the entries in messages.
void validate_rank_correlation(const Eigen::MatrixXd& spearman, const std::vector<std::string>& names,
                               std::string_view location);

// Iman-Conover makes the Pearson correlation of the normal scores equal the matrix it is given;
// for a bivariate normal the Spearman correlation is then (6/pi) asin(rho/2) (Pearson 1907), so
// a Spearman target S is converted with rho = 2 sin(pi S / 6), element by element.
Eigen::MatrixXd spearman_to_normal_correlation(const Eigen::MatrixXd& spearman);
Eigen::MatrixXd normal_to_spearman_correlation(const Eigen::MatrixXd& normal);

struct ImanConoverTarget {
  std::vector<std::string> names;
  Eigen::MatrixXd requested_spearman;  // as given
  Eigen::MatrixXd normal_correlation;  // rho, positive definite (repaired when needed)
  Eigen::MatrixXd target_spearman;     // (6/pi) asin(rho/2): the requested one unless repaired
  bool repaired = false;
  std::string warning;                 // set when repaired: what happened and the repaired matrix
};

// Validates `spearman` (see above), converts it, and when rho is not positive definite replaces
// it by the nearest correlation matrix with eigenvalues >= 1e-6 (Higham 2002) and explains
// that in `warning`, printing the repaired Spearman matrix.
ImanConoverTarget make_iman_conover_target(const Eigen::MatrixXd& spearman, const std::vector<std::string>& names,
                                           std::string_view location);

// A matrix as an aligned text table with row and column labels (for messages and summaries).
std::string format_matrix_table(const Eigen::MatrixXd& matrix, const std::vector<std::string>& names,
                                int precision = 4);

}  // namespace growthuq
