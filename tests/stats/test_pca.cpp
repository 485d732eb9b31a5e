// Correlation-matrix PCA: closed forms, a known population correlation, a second eigensolver
// (GSL's symmetric QR) on the sample correlation, and the properties of the result.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <gsl/gsl_eigen.h>

#include "growthuq/stats/pca.hpp"

using namespace growthuq;

namespace {

// Sample correlation by explicit sums (independent of the library's standardization).
Eigen::MatrixXd sample_correlation(const Eigen::MatrixXd& data) {
  const Eigen::Index n = data.rows(), m = data.cols();
  Eigen::MatrixXd result(m, m);
  for (Eigen::Index a = 0; a < m; ++a) {
    for (Eigen::Index b = 0; b < m; ++b) {
      double mean_a = 0, mean_b = 0;
      for (Eigen::Index i = 0; i < n; ++i) mean_a += data(i, a), mean_b += data(i, b);
      mean_a /= static_cast<double>(n), mean_b /= static_cast<double>(n);
      double sab = 0, saa = 0, sbb = 0;
      for (Eigen::Index i = 0; i < n; ++i) {
        sab += (data(i, a) - mean_a) * (data(i, b) - mean_b);
        saa += (data(i, a) - mean_a) * (data(i, a) - mean_a);
        sbb += (data(i, b) - mean_b) * (data(i, b) - mean_b);
      }
      result(a, b) = sab / std::sqrt(saa * sbb);
    }
  }
  return result;
}

Eigen::MatrixXd correlated_normals(const Eigen::MatrixXd& correlation, Eigen::Index n, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd z(n, correlation.rows());
  for (Eigen::Index i = 0; i < z.size(); ++i) z.data()[i] = normal(engine);
  const Eigen::MatrixXd lower = correlation.llt().matrixL();
  return z * lower.transpose();
}

void check_properties(const PcaResult& pca) {
  const Eigen::Index m = pca.loadings.rows();
  CHECK(pca.explained_variance_ratio.sum() == doctest::Approx(1.0).epsilon(1e-14));
  for (Eigen::Index c = 0; c + 1 < m; ++c) CHECK(pca.explained_variance_ratio(c) >= pca.explained_variance_ratio(c + 1));
  CHECK(pca.explained_variance_ratio.minCoeff() >= 0.0);
  // Eigen's Jacobi/QR eigenvectors are orthonormal to rounding: 1e-12 for m <= 10.
  CHECK((pca.loadings.transpose() * pca.loadings - Eigen::MatrixXd::Identity(m, m)).cwiseAbs().maxCoeff() < 1e-12);
  // Sign convention: the first entry whose magnitude is the largest (to 1e-10 relative) is positive.
  for (Eigen::Index c = 0; c < m; ++c) {
    const double largest = pca.loadings.col(c).cwiseAbs().maxCoeff();
    Eigen::Index first = 0;
    while (std::abs(pca.loadings(first, c)) < largest * (1 - 1e-10)) ++first;
    CHECK(pca.loadings(first, c) > 0);
  }
}

}  // namespace

TEST_CASE("two variables: ratios (1 +- r)/2 and loadings (1, +-1)/sqrt(2)") {
  // For a 2 x 2 correlation matrix [[1, r], [r, 1]] the eigenvalues are 1 +- r with vectors
  // (1, 1)/sqrt 2 and (1, -1)/sqrt 2 (closed form).
  Eigen::MatrixXd data(6, 2);
  data << 1.0, 2.1, 2.0, 3.9, 3.0, 6.2, 4.0, 7.8, 5.0, 10.5, 6.5, 12.0;
  const double r = sample_correlation(data)(0, 1);
  REQUIRE(r > 0.9);
  const PcaResult pca = correlation_pca(data);
  check_properties(pca);
  // Rounding of the standardization and of the 2 x 2 eigensolver: 1e-13.
  CHECK(pca.explained_variance_ratio(0) == doctest::Approx((1 + r) / 2).epsilon(1e-13));
  CHECK(pca.explained_variance_ratio(1) == doctest::Approx((1 - r) / 2).epsilon(1e-13));
  const double h = 1 / std::sqrt(2.0);
  CHECK(pca.loadings(0, 0) == doctest::Approx(h).epsilon(1e-13));
  CHECK(pca.loadings(1, 0) == doctest::Approx(h).epsilon(1e-13));
  // Equal magnitudes: the tie rule makes the first entry positive.
  CHECK(pca.loadings(0, 1) == doctest::Approx(h).epsilon(1e-13));
  CHECK(pca.loadings(1, 1) == doctest::Approx(-h).epsilon(1e-13));

  // A negative correlation exchanges the vectors.
  data.col(1) = -data.col(1);
  const PcaResult negative = correlation_pca(data);
  CHECK(negative.explained_variance_ratio(0) == doctest::Approx((1 + r) / 2).epsilon(1e-13));
  CHECK(negative.loadings(0, 0) == doctest::Approx(h).epsilon(1e-13));
  CHECK(negative.loadings(1, 0) == doctest::Approx(-h).epsilon(1e-13));
}

TEST_CASE("data drawn with a known correlation give its eigen-decomposition") {
  // Population correlation R and its decomposition (numpy 1.24.2, signs by the largest entry):
  //   /usr/bin/python3 -c "import numpy as np; R=np.array([[1,.6,.3],[.6,1,.5],[.3,.5,1]]);
  //   w,v=np.linalg.eigh(R); print(w[::-1]/3, v[:,::-1])"
  Eigen::MatrixXd population(3, 3);
  population << 1, .6, .3, .6, 1, .5, .3, .5, 1;
  const double ratios[] = {0.64792694, 0.23562616, 0.1164469};
  Eigen::MatrixXd vectors(3, 3);
  vectors << 0.56998455, -0.60911437, -0.55145017, 0.63719027, -0.09604819, 0.76469818, 0.51875445,
      0.78724483, -0.33337576;
  // Different scales and offsets per column: correlation PCA must not see them.
  Eigen::MatrixXd data = correlated_normals(population, 200000, 7);
  data.col(0) = data.col(0) * 1e-6;
  data.col(2) = (data.col(2).array() * 250.0 + 40.0).matrix();
  const PcaResult pca = correlation_pca(data);
  check_properties(pca);
  // With n = 2e5 a sample correlation is off by ~(1 - r^2)/sqrt(n) <= 0.0023; eigenvalues move by
  // about as much (ratios by a third of it), eigenvectors by that over the eigenvalue gap (0.36):
  // ~0.007. Tolerances: 0.005 on ratios, 0.03 on loadings (>= 4 standard errors).
  for (Eigen::Index c = 0; c < 3; ++c) {
    CAPTURE(c);
    CHECK(std::abs(pca.explained_variance_ratio(c) - ratios[c]) < 0.005);
    for (Eigen::Index r = 0; r < 3; ++r) CHECK(std::abs(pca.loadings(r, c) - vectors(r, c)) < 0.03);
  }
}

TEST_CASE("PCA equals GSL's eigen-decomposition of the sample correlation") {
  Eigen::MatrixXd population(4, 4);
  population << 1, .7, -.2, .1, .7, 1, -.4, .3, -.2, -.4, 1, .5, .1, .3, .5, 1;
  Eigen::MatrixXd data = correlated_normals(population, 500, 11);
  data.col(3) = data.col(3).array().exp().matrix();  // a skewed column too
  const Eigen::MatrixXd correlation = sample_correlation(data);

  gsl_matrix* a = gsl_matrix_alloc(4, 4);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) gsl_matrix_set(a, i, j, correlation(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
  gsl_vector* values = gsl_vector_alloc(4);
  gsl_matrix* vectors = gsl_matrix_alloc(4, 4);
  gsl_eigen_symmv_workspace* workspace = gsl_eigen_symmv_alloc(4);
  gsl_eigen_symmv(a, values, vectors, workspace);
  gsl_eigen_symmv_sort(values, vectors, GSL_EIGEN_SORT_VAL_DESC);

  const PcaResult pca = correlation_pca(data);
  check_properties(pca);
  for (std::size_t c = 0; c < 4; ++c) {
    CAPTURE(c);
    // Two backward-stable solvers on matrices equal to ~1e-15: eigenvalues agree to ~1e-14,
    // vectors to ~1e-14 / gap (gaps here > 0.1): tolerance 1e-11.
    CHECK(pca.explained_variance_ratio(static_cast<Eigen::Index>(c)) ==
          doctest::Approx(gsl_vector_get(values, c) / 4).epsilon(1e-11));
    double dot = 0;
    for (std::size_t r = 0; r < 4; ++r) dot += pca.loadings(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) * gsl_matrix_get(vectors, r, c);
    CHECK(std::abs(dot) == doctest::Approx(1.0).epsilon(1e-11));
  }
  gsl_eigen_symmv_free(workspace);
  gsl_matrix_free(vectors);
  gsl_vector_free(values);
  gsl_matrix_free(a);
}

TEST_CASE("collinear columns give a zero component, not a negative or NaN one") {
  Eigen::MatrixXd data(5, 3);
  data << 1, 3, 0.5, 2, 5, -1.0, 3, 7, 2.0, 4, 9, 0.1, 5, 11, 1.7;  // column 2 = 2 column 1 + 1
  const PcaResult pca = correlation_pca(data);
  check_properties(pca);
  CHECK(pca.explained_variance_ratio.allFinite());
  CHECK(pca.loadings.allFinite());
  CHECK(pca.explained_variance_ratio(2) < 1e-15);
}

TEST_CASE("PCA rejects what it cannot standardize") {
  Eigen::MatrixXd constant(4, 2);
  constant << 1, 2, 1, 3, 1, 4, 1, 5;
  CHECK_THROWS_WITH_AS(correlation_pca(constant), "correlation_pca: column 1 is constant", std::invalid_argument);
  CHECK_THROWS_AS(correlation_pca(Eigen::MatrixXd(1, 3)), std::invalid_argument);
  Eigen::MatrixXd with_nan = Eigen::MatrixXd::Ones(3, 2);
  with_nan(1, 1) = std::nan("");
  CHECK_THROWS_AS(correlation_pca(with_nan), std::invalid_argument);
}
