// Shapley effects (Eqs. (S3)-(S5), src/sensitivity/README.md): the closed form of the linear
// Gaussian model against a hand derivation and the independent case, and the estimator (exact
// permutations up to 6 inputs, random ones beyond) against that closed form, with its sum
// property and the coverage of its interval.
#include <doctest/doctest.h>

#include <cmath>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "growthuq/distributions/standard_normal.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/sensitivity/shapley.hpp"

using namespace growthuq;

namespace {

// The model Y = b^T X (one output), X in its own units.
BatchModel linear_model(const Eigen::VectorXd& b) {
  return [b](const Eigen::MatrixXd& x) -> Eigen::MatrixXd { return x * b; };
}

// N(0, Sigma) as marginals N(0, Sigma_ii) and the Gaussian copula of Sigma's correlation.
std::vector<Quantile> normal_marginals(const Eigen::MatrixXd& sigma) {
  std::vector<Quantile> marginals;
  for (Eigen::Index i = 0; i < sigma.rows(); ++i) {
    const double sd = std::sqrt(sigma(i, i));
    marginals.push_back([sd](std::span<const double> u, std::span<double> x) {
      standard_normal_quantiles(u, x);
      for (double& value : x) value *= sd;
    });
  }
  return marginals;
}
Eigen::MatrixXd correlation_of(const Eigen::MatrixXd& sigma) {
  const Eigen::VectorXd sd = sigma.diagonal().cwiseSqrt();
  return sigma.array() / (sd * sd.transpose()).array();
}

Eigen::MatrixXd test_sigma() {  // as test_rank_first_order.cpp: correlations 0.3 and -0.6
  Eigen::MatrixXd sigma(3, 3);
  sigma << 1.0, 0.6, 0.0,  //
      0.6, 4.0, -1.2,      //
      0.0, -1.2, 1.0;
  return sigma;
}

}  // namespace

TEST_CASE("Shapley closed form: two correlated inputs by hand, independent inputs, the sum") {
  // X1, X2 standard normal with correlation rho, Y = b1 X1 + b2 X2: c({1}) = E Var(Y | X2) =
  // b1^2 (1 - rho^2), c({2}) = b2^2 (1 - rho^2), V = b1^2 + b2^2 + 2 rho b1 b2, and
  // Sh_1 = (c({1}) + V - c({2})) / 2 = b1^2 (1 - rho^2 / 2) + rho b1 b2 + b2^2 rho^2 / 2.
  const double rho = 0.7, b1 = 2.0, b2 = -0.5;
  Eigen::Matrix2d sigma;
  sigma << 1, rho, rho, 1;
  const Eigen::VectorXd sh = linear_gaussian_shapley(sigma, Eigen::Vector2d(b1, b2));
  CHECK(sh(0) == doctest::Approx(b1 * b1 * (1 - rho * rho / 2) + rho * b1 * b2 + b2 * b2 * rho * rho / 2).epsilon(1e-13));
  CHECK(sh(1) == doctest::Approx(b2 * b2 * (1 - rho * rho / 2) + rho * b1 * b2 + b1 * b1 * rho * rho / 2).epsilon(1e-13));
  // Independent inputs: Sh_i = b_i^2 Sigma_ii (no dependence, no interaction to share).
  const Eigen::VectorXd independent = linear_gaussian_shapley(Eigen::Vector3d(1, 4, 0.25).asDiagonal(), Eigen::Vector3d(1, 0.5, 2));
  CHECK(independent(0) == doctest::Approx(1.0).epsilon(1e-13));
  CHECK(independent(1) == doctest::Approx(1.0).epsilon(1e-13));
  CHECK(independent(2) == doctest::Approx(1.0).epsilon(1e-13));
  // Correlated: the effects sum to b^T Sigma b = 2.6, X3 (b3 = 0) gets a share through X2.
  const Eigen::VectorXd correlated = linear_gaussian_shapley(test_sigma(), Eigen::Vector3d(1, 0.5, 0));
  CHECK(correlated.sum() == doctest::Approx(2.6).epsilon(1e-13));
  CHECK(correlated(2) > 0.05);
}

TEST_CASE("Shapley estimator, exact permutations: the linear Gaussian model's closed form, and the sum") {
  const Eigen::MatrixXd sigma = test_sigma();
  const Eigen::VectorXd b = Eigen::Vector3d(1, 0.5, 0);
  const Eigen::VectorXd exact = linear_gaussian_shapley(sigma, b);
  const ShapleyEffects sh = shapley_effects(linear_model(b), normal_marginals(sigma), correlation_of(sigma),
                                            {.variance_samples = 20000, .outer = 4000, .inner = 3, .sections = 10, .key = 5});
  CHECK(sh.exact_permutations);
  CHECK(sh.model_runs == 20000 + 6 * 4000 * 3);
  // Sum property (Eq. (S3)): exactly the estimated variance, each section's and so the mean's.
  CHECK(sh.effect.col(0).sum() == doctest::Approx(sh.variance(0)).epsilon(1e-12));
  CHECK(sh.variance(0) == doctest::Approx(2.6).epsilon(0.03));  // sd of a variance from 20000 normal draws: 1 %
  CHECK(sh.share.col(0).sum() == doctest::Approx(1.0).epsilon(1e-12));  // each section's shares sum to 1
  for (Eigen::Index i = 0; i < 3; ++i) {
    CAPTURE(i);
    MESSAGE("Sh_" << i + 1 << ": " << sh.effect(i, 0) << " [" << sh.low(i, 0) << ", " << sh.high(i, 0) << "], exact " << exact(i));
    // The interval's half width is 0.03-0.05 here (standard error about 0.02); 0.08 is 4 of them.
    CHECK(std::abs(sh.effect(i, 0) - exact(i)) < 0.08);
    CHECK(sh.high(i, 0) - sh.low(i, 0) < 0.12);
  }
}

TEST_CASE("Shapley estimator, random permutations beyond 6 inputs: closed form and sum") {
  // Seven inputs: the correlated three of test_sigma and four independent ones.
  Eigen::MatrixXd sigma = Eigen::MatrixXd::Identity(7, 7);
  sigma.topLeftCorner(3, 3) = test_sigma();
  sigma(3, 3) = 0.5;
  Eigen::VectorXd b(7);
  b << 1, 0.5, 0, 1, 0.3, -0.7, 0.1;
  const Eigen::VectorXd exact = linear_gaussian_shapley(sigma, b);
  const ShapleyEffects sh = shapley_effects(linear_model(b), normal_marginals(sigma), correlation_of(sigma),
                                            {.variance_samples = 20000, .outer = 1, .inner = 3, .permutations = 8000,
                                             .sections = 10, .key = 6});
  CHECK_FALSE(sh.exact_permutations);
  CHECK(sh.effect.col(0).sum() == doctest::Approx(sh.variance(0)).epsilon(1e-12));
  for (Eigen::Index i = 0; i < 7; ++i) {
    CAPTURE(i);
    MESSAGE("Sh_" << i + 1 << ": " << sh.effect(i, 0) << " [" << sh.low(i, 0) << ", " << sh.high(i, 0) << "], exact " << exact(i));
    // Half widths 0.04-0.07 at 8000 permutations with N_o = 1 (Song et al.'s choice; 0.06-0.09
    // at 4000, measured), so standard errors up to 0.035: 0.12 is about 3.5 of the widest.
    CHECK(std::abs(sh.effect(i, 0) - exact(i)) < 0.12);
  }
}

TEST_CASE("Shapley estimator: the interval covers the exact effects at its rate") {
  // 100 independent runs (keys) of the exact-permutation estimator on the 3-input model.
  const Eigen::MatrixXd sigma = test_sigma();
  const Eigen::VectorXd b = Eigen::Vector3d(1, 0.5, 0);
  const Eigen::VectorXd exact = linear_gaussian_shapley(sigma, b);
  std::size_t covered = 0, total = 0;
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    const ShapleyEffects sh = shapley_effects(linear_model(b), normal_marginals(sigma), correlation_of(sigma),
                                              {.variance_samples = 2000, .outer = 400, .inner = 3, .sections = 10,
                                               .key = derive_key(seed, "coverage")});
    for (Eigen::Index i = 0; i < 3; ++i) {
      covered += sh.low(i, 0) <= exact(i) && exact(i) <= sh.high(i, 0);
      ++total;
    }
  }
  const double rate = static_cast<double>(covered) / static_cast<double>(total);
  MESSAGE("Shapley 95 % interval coverage: " << covered << " of " << total << " = " << rate);
  // 300 intervals (3 per run, dependent): a binomial sd of 1.3 %; the band allows about 3.
  CHECK(rate >= 0.91);
  CHECK(rate <= 0.99);
}
