// Non-negative linear least squares: the amplitudes of a Prony series for fixed relaxation
// times (variable projection). Eigen 3.4 has no NNLS module, so this is Lawson and Hanson's
// active-set algorithm (Solving Least Squares Problems, 1974, chapter 23).
#pragma once

#include <Eigen/Dense>

namespace growthuq {

// x >= 0 minimizing |A x - b|_2. Columns of A should be of comparable scale.
Eigen::VectorXd solve_nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

}  // namespace growthuq
