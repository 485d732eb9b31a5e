// Nearest correlation matrix: Higham's (2002) published example, and properties of the repair
// of a rank correlation target.
#include <doctest/doctest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "growthuq/core/error.hpp"
#include "growthuq/correlation/nearest_correlation.hpp"
#include "growthuq/correlation/rank_correlation_target.hpp"

using namespace growthuq;

namespace {

Eigen::MatrixXd matrix3(std::initializer_list<double> values) {
  Eigen::MatrixXd a(3, 3);
  auto it = values.begin();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a(i, j) = *it++;
  return a;
}

// Eigenvalue clipping followed by rescaling to a unit diagonal: the simpler repair.
Eigen::MatrixXd clip_and_rescale(const Eigen::MatrixXd& a) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(a);
  Eigen::MatrixXd x = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
  const Eigen::VectorXd s = x.diagonal().cwiseSqrt().cwiseInverse();
  return s.asDiagonal() * x * s.asDiagonal();
}

}  // namespace

TEST_CASE("Higham 2002 section 4 example: A = [1 1 0; 1 1 1; 0 1 1]") {
  // Published result (Higham 2002, p. 340): off-diagonals 0.7607 and 0.1573, to 4 decimals.
  const Eigen::MatrixXd a = matrix3({1, 1, 0, 1, 1, 1, 0, 1, 1});
  const NearestCorrelationResult result = nearest_correlation_matrix(a);
  CHECK(result.converged);
  const Eigen::MatrixXd& x = result.matrix;
  CHECK(std::abs(x(0, 1) - 0.7607) < 5e-5);
  CHECK(std::abs(x(1, 2) - 0.7607) < 5e-5);
  CHECK(std::abs(x(0, 2) - 0.1573) < 5e-5);
  CHECK(x.diagonal().isOnes(0));
  // It is a correlation matrix (eigenvalues >= 0 up to the convergence tolerance) and nearer
  // to A than the clipped-and-rescaled one (0.5376 vs Higham's 0.5278).
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(x);
  CHECK(eigen.eigenvalues().minCoeff() > -1e-9);
  CHECK((x - a).norm() == doctest::Approx(0.5277904635818285).epsilon(1e-8));
  CHECK((x - a).norm() < (clip_and_rescale(a) - a).norm());
}

TEST_CASE("a valid but unattainable Spearman target is repaired with a warning") {
  // k-h and h-d strongly positive but k-d strongly negative: impossible together.
  const std::vector<std::string> names{"k", "h", "d"};
  const Eigen::MatrixXd s = matrix3({1, 0.9, -0.9, 0.9, 1, 0.9, -0.9, 0.9, 1});
  const ImanConoverTarget target = make_iman_conover_target(s, names, "m.csv");
  CHECK(target.repaired);
  CHECK(target.warning.find("m.csv: warning: the rank correlation target is not attainable") == 0);
  CHECK(target.warning.find("nearest correlation matrix") != std::string::npos);
  const Eigen::LLT<Eigen::MatrixXd> cholesky(target.normal_correlation);
  CHECK(cholesky.info() == Eigen::Success);
  CHECK(target.normal_correlation.diagonal().isOnes(0));
  CHECK(target.normal_correlation.isApprox(target.normal_correlation.transpose(), 0));
  // The repair moves the matrix no further than the simple clipping repair does (here they
  // coincide), up to the eigenvalue floor of 1e-6, which moves it by at most ~sqrt(3) 1e-6.
  const Eigen::MatrixXd rho = spearman_to_normal_correlation(s);
  CHECK((target.normal_correlation - rho).norm() <= (clip_and_rescale(rho) - rho).norm() + 1e-5);
  // A target that is fine is left alone.
  const Eigen::MatrixXd fine = matrix3({1, 0.3, 0.1, 0.3, 1, 0.2, 0.1, 0.2, 1});
  const ImanConoverTarget kept = make_iman_conover_target(fine, names, "m.csv");
  CHECK_FALSE(kept.repaired);
  CHECK(kept.target_spearman == fine);
}

TEST_CASE("Spearman <-> normal-score correlation conversion (Pearson 1907)") {
  const Eigen::MatrixXd s = matrix3({1, 0.5, -0.3, 0.5, 1, 0, -0.3, 0, 1});
  const Eigen::MatrixXd rho = spearman_to_normal_correlation(s);
  // 2 sin(pi/12) = 0.5176380902050415 (mpmath: 2*sin(pi/12))
  CHECK(rho(0, 1) == doctest::Approx(0.5176380902050415).epsilon(1e-15));
  CHECK(rho(1, 2) == 0.0);
  CHECK((normal_to_spearman_correlation(rho) - s).cwiseAbs().maxCoeff() < 1e-15);
}

TEST_CASE("invalid rank correlation matrices are input errors") {
  const std::vector<std::string> names{"k", "h", "d"};
  CHECK_THROWS_WITH_AS(validate_rank_correlation(matrix3({1, 0.2, 0, 0.3, 1, 0, 0, 0, 1}), names, "m.csv"),
                       "m.csv: entry (k, h) = '0.2': expected a symmetric matrix: entry (h, k) is 0.3", InputError);
  CHECK_THROWS_WITH_AS(validate_rank_correlation(matrix3({1, 1.2, 0, 1.2, 1, 0, 0, 0, 1}), names, "m.csv"),
                       "m.csv: entry (k, h) = '1.2': expected a number in [-1, 1]", InputError);
  CHECK_THROWS_AS(validate_rank_correlation(matrix3({1, 0, 0, 0, 0.9, 0, 0, 0, 1}), names, "m.csv"), InputError);
  CHECK_THROWS_AS(validate_rank_correlation(Eigen::MatrixXd::Identity(2, 3), names, "m.csv"), InputError);
  CHECK_THROWS_AS(validate_rank_correlation(matrix3({1, NAN, 0, NAN, 1, 0, 0, 0, 1}), names, "m.csv"), InputError);
}
