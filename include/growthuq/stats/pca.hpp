// Principal component analysis of standardized columns (the eigen-decomposition of their
// correlation matrix, Jolliffe 2002, "Principal Component Analysis", 2.3), as the published
// study reports it per plant line for inputs and outputs together.
#pragma once

#include <cstddef>

#include <Eigen/Core>

namespace growthuq {

struct PcaResult {
  // Share of the total standardized variance (= number of variables) per component,
  // descending; sums to 1. Eigenvalues below 0 from rounding (collinear columns) count as 0.
  Eigen::VectorXd explained_variance_ratio;
  // variables x components; column c is the unit-norm eigenvector of component c, so the matrix
  // is orthogonal. Sign convention: in each column the entry of largest magnitude is positive;
  // on a tie (magnitudes within 1e-10 relative) the first of them, so the sign is reproducible.
  Eigen::MatrixXd loadings;
};

// PCA of `data` (rows = samples, columns = variables), each column centred and scaled by its
// standard deviation (n - 1). std::invalid_argument when there are fewer than 2 rows, no
// columns, a non-finite value or a constant column (its standardized values are undefined):
// callers (analyze_line) filter those first and say so.
PcaResult correlation_pca(const Eigen::MatrixXd& data);

// The same from the correlation matrix itself (symmetric, unit diagonal, finite;
// std::invalid_argument when not square or not finite), for callers that computed it without
// holding the data as one matrix.
PcaResult pca_of_correlation(const Eigen::MatrixXd& correlation);

}  // namespace growthuq
