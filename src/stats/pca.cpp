#include "growthuq/stats/pca.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>

namespace growthuq {

namespace {

constexpr double tie_tolerance = 1e-10;

}  // namespace

PcaResult correlation_pca(const Eigen::MatrixXd& data) {
  const Eigen::Index n = data.rows();
  const Eigen::Index m = data.cols();
  if (n < 2 || m < 1) {
    throw std::invalid_argument("correlation_pca: needs at least 2 samples and 1 variable, got " +
                                std::to_string(n) + " x " + std::to_string(m));
  }
  if (!data.allFinite()) throw std::invalid_argument("correlation_pca: data hold a non-finite value");

  // Standardize every column (centre, divide by its n - 1 standard deviation); the correlation
  // matrix is then Z^T Z / (n - 1).
  Eigen::MatrixXd standardized = data.rowwise() - data.colwise().mean();
  const Eigen::RowVectorXd sd =
      (standardized.colwise().squaredNorm() / static_cast<double>(n - 1)).cwiseSqrt();
  for (Eigen::Index j = 0; j < m; ++j) {
    if (!(sd(j) > 0)) {
      throw std::invalid_argument("correlation_pca: column " + std::to_string(j + 1) + " is constant");
    }
  }
  standardized.array().rowwise() /= sd.array();
  Eigen::MatrixXd correlation = Eigen::MatrixXd::Zero(m, m);
  correlation.selfadjointView<Eigen::Lower>().rankUpdate(standardized.transpose(),
                                                         1.0 / static_cast<double>(n - 1));
  correlation = correlation.selfadjointView<Eigen::Lower>();

  return pca_of_correlation(correlation);
}

PcaResult pca_of_correlation(const Eigen::MatrixXd& correlation) {
  const Eigen::Index m = correlation.rows();
  if (m < 1 || correlation.cols() != m || !correlation.allFinite()) {
    throw std::invalid_argument("pca_of_correlation: needs a finite square matrix of at least 1 x 1");
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(correlation);
  if (solver.info() != Eigen::Success) throw std::runtime_error("correlation_pca: eigen-decomposition failed");

  // Eigen returns ascending eigenvalues: reverse them and their vectors.
  PcaResult result;
  result.explained_variance_ratio.resize(m);
  result.loadings.resize(m, m);
  double total = 0;
  for (Eigen::Index c = 0; c < m; ++c) {
    const Eigen::Index source = m - 1 - c;
    const double eigenvalue = std::max(0.0, solver.eigenvalues()(source));
    result.explained_variance_ratio(c) = eigenvalue;
    total += eigenvalue;
    Eigen::VectorXd vector = solver.eigenvectors().col(source);
    // Magnitudes equal up to rounding count as a tie, so the sign does not hinge on the last bit.
    const double largest = vector.cwiseAbs().maxCoeff();
    Eigen::Index first = 0;
    while (std::abs(vector(first)) < largest * (1 - tie_tolerance)) ++first;
    if (vector(first) < 0) vector = -vector;
    result.loadings.col(c) = vector;
  }
  // The trace of a correlation matrix is m; dividing by the clipped sum keeps the ratios summing
  // to 1 when rounding made an eigenvalue slightly negative.
  result.explained_variance_ratio /= total;
  return result;
}

}  // namespace growthuq
