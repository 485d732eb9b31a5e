#include "growthuq/correlation/nearest_correlation.hpp"

#include <Eigen/Eigenvalues>

namespace growthuq {

namespace {

// Projection onto the positive semidefinite cone (eigenvalues >= floor).
Eigen::MatrixXd project_to_psd(const Eigen::MatrixXd& r, double floor) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(r);
  const Eigen::VectorXd clipped = eigen.eigenvalues().cwiseMax(floor);
  Eigen::MatrixXd x = eigen.eigenvectors() * clipped.asDiagonal() * eigen.eigenvectors().transpose();
  return 0.5 * (x + x.transpose());
}

}  // namespace

NearestCorrelationResult nearest_correlation_matrix(const Eigen::MatrixXd& a, const NearestCorrelationOptions& options) {
  NearestCorrelationResult result;
  Eigen::MatrixXd y = a;
  Eigen::MatrixXd dykstra = Eigen::MatrixXd::Zero(a.rows(), a.cols());
  Eigen::MatrixXd x = a;
  for (result.iterations = 1; result.iterations <= options.max_iterations; ++result.iterations) {
    const Eigen::MatrixXd r = y - dykstra;
    x = project_to_psd(r, options.min_eigenvalue);
    dykstra = x - r;
    const Eigen::MatrixXd y_previous = y;
    y = x;
    y.diagonal().setOnes();  // projection onto the unit-diagonal matrices
    const double change = (y - y_previous).norm() / y.norm();
    if (change < options.tolerance && (y - x).norm() / y.norm() < options.tolerance) {
      result.converged = true;
      break;
    }
  }
  if (options.min_eigenvalue > 0) {
    // The last unit-diagonal projection may push an eigenvalue just below the floor; one more
    // cone projection and a diagonal rescaling D^-1/2 X D^-1/2 make the result positive
    // definite with an exact unit diagonal.
    x = project_to_psd(y, options.min_eigenvalue);
    const Eigen::VectorXd scale = x.diagonal().cwiseSqrt().cwiseInverse();
    y = scale.asDiagonal() * x * scale.asDiagonal();
    y.diagonal().setOnes();
  }
  result.matrix = y;
  return result;
}

}  // namespace growthuq
