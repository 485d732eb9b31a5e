#include "relaxation/nnls.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace growthuq {

Eigen::VectorXd solve_nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  const Eigen::Index n = A.cols();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(static_cast<std::size_t>(n), false);
  // Tolerance on the dual vector w = A^T (b - A x), relative to its natural scale.
  const double tolerance = 10.0 * std::numeric_limits<double>::epsilon() * A.norm() * b.norm();

  // Least squares restricted to the passive columns; zero elsewhere.
  auto passive_solution = [&]() {
    std::vector<Eigen::Index> columns;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (passive[static_cast<std::size_t>(j)]) columns.push_back(j);
    }
    Eigen::MatrixXd sub(A.rows(), static_cast<Eigen::Index>(columns.size()));
    for (std::size_t c = 0; c < columns.size(); ++c) sub.col(static_cast<Eigen::Index>(c)) = A.col(columns[c]);
    const Eigen::VectorXd coefficients = sub.colPivHouseholderQr().solve(b);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    for (std::size_t c = 0; c < columns.size(); ++c) z(columns[c]) = coefficients(static_cast<Eigen::Index>(c));
    return z;
  };

  // Lawson and Hanson (1974), algorithm NNLS: the outer loop frees the column with the largest
  // positive dual value, the inner loop steps back towards feasibility when a passive
  // coefficient would turn negative. 3n outer iterations bound the (finite) active-set walk.
  for (Eigen::Index outer = 0; outer < 3 * n + 3; ++outer) {
    const Eigen::VectorXd w = A.transpose() * (b - A * x);
    Eigen::Index entering = -1;
    double largest = tolerance;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!passive[static_cast<std::size_t>(j)] && w(j) > largest) {
        largest = w(j);
        entering = j;
      }
    }
    if (entering < 0) break;
    passive[static_cast<std::size_t>(entering)] = true;

    for (Eigen::Index inner = 0; inner < 3 * n + 3; ++inner) {
      const Eigen::VectorXd z = passive_solution();
      double step = 1.0;
      bool feasible = true;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (passive[static_cast<std::size_t>(j)] && z(j) <= 0.0) {
          feasible = false;
          const double denominator = x(j) - z(j);
          if (denominator > 0.0) step = std::min(step, x(j) / denominator);
        }
      }
      if (feasible) {
        x = z;
        break;
      }
      x += step * (z - x);
      const double zero = 64.0 * std::numeric_limits<double>::epsilon() * x.cwiseAbs().maxCoeff();
      for (Eigen::Index j = 0; j < n; ++j) {
        if (passive[static_cast<std::size_t>(j)] && x(j) <= zero) {
          passive[static_cast<std::size_t>(j)] = false;
          x(j) = 0.0;
        }
      }
    }
  }
  return x;
}

}  // namespace growthuq
