// The nearest correlation matrix (Frobenius norm) to a symmetric matrix that is not one,
// e.g. a rank correlation target typed by hand or assembled from partial studies that is not
// positive definite. Alternating projections with Dykstra's correction (Higham 2002,
// "Computing the nearest correlation matrix - a problem from finance", IMA J. Numer. Anal.
// 22:329-343, Algorithm 3.3 with W = I).
#pragma once

#include <Eigen/Core>

namespace growthuq {

struct NearestCorrelationOptions {
  // Eigenvalues are projected to at least this value. 0 gives Higham's nearest positive
  // semidefinite correlation matrix; a small positive floor gives a positive definite one that a
  // Cholesky factorization accepts.
  double min_eigenvalue = 0.0;
  double tolerance = 1e-10;  // stop when successive iterates differ by less, relative (Frobenius)
  int max_iterations = 10000;
};

struct NearestCorrelationResult {
  Eigen::MatrixXd matrix;  // symmetric, unit diagonal, eigenvalues >= min_eigenvalue (to tolerance)
  int iterations = 0;
  bool converged = false;
};

// `a` must be symmetric with finite entries (not checked here; see rank_correlation_target.hpp).
// With min_eigenvalue > 0 the returned matrix is rescaled to an exact unit diagonal after the
// last projection, so it is positive definite.
NearestCorrelationResult nearest_correlation_matrix(const Eigen::MatrixXd& a,
                                                    const NearestCorrelationOptions& options = {});

}  // namespace growthuq
